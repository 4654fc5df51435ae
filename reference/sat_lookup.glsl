// sat_lookup.glsl: box average of the moment map from its summed-area table.
// Reference solution. Stage contract: docs/stage_contract.md.
//
// Included by the lighting pass (and by shaders/sat_resolve.comp) when the filter is a SAT.
// `sat` is the table written by sat.comp, bound with nearest filtering, read with texelFetch.
// Texel i covers [i, i + 1); box centres and sizes are in texel units.
//
// The table is stored with an offset (see sat.comp): independent SAT_TILE² tiles, each
// holding, in local coordinates with a = m(0, 0) of the tile, for x, y >= 1
//     T(x, y) = Σ_{1<=i<=x, 1<=j<=y} (m(i,j) - m(0,j) - m(i,0) + a)      ("interior")
//     A(x) = T(x, 0) = Σ_{1<=i<=x} (m(i,0) - a),   B(y) = T(0, y) = Σ_{1<=j<=y} (m(0,j) - a).
// The tile's own summed-area table follows as (take T(x, y) = 0 if x or y is <= 0, A(x) = 0
// for x <= 0, B(y) = 0 for y <= 0; this also gives S(-1, ·) = S(·, -1) = 0):
//     S(x, y) = T(x, y) + (y + 1)·A(x) + (x + 1)·B(y) + (x + 1)·(y + 1)·a.
// A box is cut into its parts in each tile it overlaps (1 to 4 tiles for boxes up to
// SAT_TILE texels wide); in each part's four-corner difference the last three terms of S
// collapse to exact closed forms (below), so only small sums of differences are subtracted.
// Error: <= 7e-6 for any box on 512²..4096² maps, where a plain float32 table errs by up to
// 0.8 (docs/numerics.md). The price: 25 reads for a box inside one tile, 121 for a box over
// 3 x 3 tiles (below), instead of 16 in all.

#define SAT_TILE 32  // must equal SAT_TILE in sat.comp

// Interior part T of the tile at `origin`, at local index i; 0 on the tile's first row and
// column and left of / below it.
vec4 satInterior(sampler2D sat, ivec2 origin, ivec2 i)
{
    vec4 t = texelFetch(sat, origin + max(i, ivec2(0)), 0);  // never fetch out of bounds
    return (i.x <= 0 || i.y <= 0) ? vec4(0.0) : t;
}

// A (axis 0: the tile's first row) or B (axis 1: its first column), linearly interpolated at
// local index t = e - 1 for a local edge position e in [0, size]; 0 at indices <= 0.
vec4 satEdge(sampler2D sat, ivec2 origin, float e, int size, int axis)
{
    float t = e - 1.0;
    int i = clamp(int(floor(t)), -1, max(size - 2, -1));
    float f = t - float(i);
    ivec2 step = axis == 0 ? ivec2(1, 0) : ivec2(0, 1);
    vec4 v0 = i <= 0 ? vec4(0.0) : texelFetch(sat, origin + i * step, 0);
    vec4 v1 = i + 1 <= 0 ? vec4(0.0) : texelFetch(sat, origin + (i + 1) * step, 0);
    return mix(v0, v1, f);
}

// Interior part of the tile's sum over [0, e.x] × [0, e.y] (local), e inside [0, size]².
// The integral of a piecewise-constant image is bilinear within each cell of the integer
// grid, so linear interpolation at e - 1 between integer indices is exact, also for
// fractional e: the box includes the fraction of the partially covered texel.
// Interpolated by hand: hardware filtering computes its weights with ~8 fractional bits.
vec4 satInteriorBelow(sampler2D sat, ivec2 origin, vec2 e, ivec2 size)
{
    vec2 t = e - 1.0;
    // Lower corner of the interpolation cell, kept in [-1, size - 2] so that i + 1 is still
    // a table index; t = size - 1 (the far edge) then gets weight f = 1.
    ivec2 i = clamp(ivec2(floor(t)), ivec2(-1), max(size - 2, ivec2(-1)));
    vec2 f = t - vec2(i);
    vec4 s00 = satInterior(sat, origin, i);
    vec4 s10 = satInterior(sat, origin, i + ivec2(1, 0));
    vec4 s01 = satInterior(sat, origin, i + ivec2(0, 1));
    vec4 s11 = satInterior(sat, origin, i + ivec2(1, 1));
    return mix(mix(s00, s10, f.x), mix(s01, s11, f.x), f.y);
}

// The part of the box [lo, hi] (map coordinates) in tile (tx, ty): the tile's origin and size,
// the part's local corners lo <= hi; false if the part is empty.
bool satPart(ivec2 mapSize, vec2 lo, vec2 hi, int tx, int ty,
             out ivec2 origin, out ivec2 size, out vec2 partLo, out vec2 partHi)
{
    origin = ivec2(tx, ty) * SAT_TILE;
    size = min(ivec2(SAT_TILE), mapSize - origin);
    partLo = max(lo - vec2(origin), vec2(0.0));
    partHi = min(hi - vec2(origin), vec2(size));
    return partHi.x > partLo.x && partHi.y > partLo.y;
}

// A part's sum is, by inclusion-exclusion, S(hi) - S(lo.x, hi.y) - S(hi.x, lo.y) + S(lo), term
// by term of S above (e = t + 1 is the interpolation position):
//     interior:        the same four-corner difference of T;
//     (y + 1)·A(x):    (hi.y - lo.y)·(A(hi.x) - A(lo.x));
//     (x + 1)·B(y):    (hi.x - lo.x)·(B(hi.y) - B(lo.y));
//     (x+1)(y+1)·a:    area·a.
// Grouped by corner instead of by part: a part's lo.x is 0 unless the part is in the box's
// first tile column (lo.y: first tile row), and T, A and B are exactly 0 there. So the terms at
// each part's hi (9 reads) are summed over every tile, those at lo.x (6 reads) over the first
// column, those at lo.y (6) over the first row, T(lo) (4) in the first tile alone: 25 reads for
// a box inside one tile as before, 64 instead of 100 for 2 x 2 tiles, 121 instead of 225 for
// 3 x 3 (wide_blur). Loops, not branches, choose what is read: the hi terms in a nested loop,
// the lo.x terms in its outer one, the lo.y terms in a loop of their own, T(lo) once. llvmpipe
// runs both sides of every branch, so only a loop's trip count can leave reads out.

// Terms at the part's hi corner, for every tile of the box.
vec4 satTermsAtHi(sampler2D sat, ivec2 origin, ivec2 size, vec2 lo, vec2 hi)
{
    vec2 extent = hi - lo;
    return satInteriorBelow(sat, origin, hi, size)
         + extent.y * satEdge(sat, origin, hi.x, size.x, 0)
         + extent.x * satEdge(sat, origin, hi.y, size.y, 1)
         + (extent.x * extent.y) * texelFetch(sat, origin, 0);
}

// Terms at the part's lo along `axis`, for the box's first tile column (axis 0) or row (1):
// T at (lo.x, hi.y) or (hi.x, lo.y), plus the extent across times A(lo.x) or B(lo.y); the box
// subtracts them. `axis` is a constant at each call, so the selects fold away.
vec4 satTermsAtLo(sampler2D sat, ivec2 origin, ivec2 size, vec2 lo, vec2 hi, int axis)
{
    vec2 corner = axis == 0 ? vec2(lo.x, hi.y) : vec2(hi.x, lo.y);
    float across = axis == 0 ? hi.y - lo.y : hi.x - lo.x;
    return satInteriorBelow(sat, origin, corner, size) + across * satEdge(sat, origin, lo[axis], size[axis], axis);
}

// Mean of the moments over the box of size boxSize (>= 1 texel, fractional allowed) centred
// at `center`, clipped to the map [0, size]. Partially covered texels count with the
// fraction covered.
vec4 satBoxAverage(sampler2D sat, vec2 center, vec2 boxSize)
{
    ivec2 size = textureSize(sat, 0);
    vec2 lo = clamp(center - 0.5 * boxSize, vec2(0.0), vec2(size));
    vec2 hi = clamp(center + 0.5 * boxSize, vec2(0.0), vec2(size));
    vec2 extent = hi - lo;
    // A box that misses the map entirely has no area: return 0, not 0 / 0.
    if (extent.x <= 0.0 || extent.y <= 0.0)
        return vec4(0.0);
    // The tiles the box overlaps (with a non-empty part): [tileLo, tileHi].
    ivec2 tileLo = ivec2(floor(lo / float(SAT_TILE)));
    ivec2 tileHi = ivec2(ceil(hi / float(SAT_TILE))) - 1;
    // do-while, not for: llvmpipe runs a loop's body again, all lanes masked off, until no
    // lane is left in it, and a for loop's last check comes at the top of a body that then
    // runs for nothing. Every box overlaps at least one tile on each axis.
    ivec2 origin, tileSize;
    vec2 partLo, partHi;
    vec4 sum = vec4(0.0);
    int ty = tileLo.y;
    do {
        int tx = tileLo.x;
        do {
            if (satPart(size, lo, hi, tx, ty, origin, tileSize, partLo, partHi))
                sum += satTermsAtHi(sat, origin, tileSize, partLo, partHi);
            ++tx;
        } while (tx <= tileHi.x);
        if (satPart(size, lo, hi, tileLo.x, ty, origin, tileSize, partLo, partHi))
            sum -= satTermsAtLo(sat, origin, tileSize, partLo, partHi, 0);
        ++ty;
    } while (ty <= tileHi.y);
    int tx = tileLo.x;
    do {
        if (satPart(size, lo, hi, tx, tileLo.y, origin, tileSize, partLo, partHi))
            sum -= satTermsAtLo(sat, origin, tileSize, partLo, partHi, 1);
        ++tx;
    } while (tx <= tileHi.x);
    if (satPart(size, lo, hi, tileLo.x, tileLo.y, origin, tileSize, partLo, partHi))
        sum += satInteriorBelow(sat, origin, partLo, tileSize);
    return sum / (extent.x * extent.y);
}
