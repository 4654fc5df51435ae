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
// 0.8 (docs/numerics.md). The price: up to 25 reads per tile part instead of 16 in all.

#include "sat_tile.glsl"  // SAT_TILE, shared with the other SAT file

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

// Sum of the moments over the local box [lo, hi] (non-empty, inside [0, size]²) of the tile
// at `origin`. Inclusion-exclusion, S(hi) - S(lo.x, hi.y) - S(hi.x, lo.y) + S(lo), term by
// term of S above (e = t + 1 is the interpolation position):
//     interior:        the same four-corner difference of T;
//     (y + 1)·A(x):    (hi.y - lo.y)·(A(hi.x) - A(lo.x));
//     (x + 1)·B(y):    (hi.x - lo.x)·(B(hi.y) - B(lo.y));
//     (x+1)(y+1)·a:    area·a.
vec4 satTileSum(sampler2D sat, ivec2 origin, ivec2 size, vec2 lo, vec2 hi)
{
    vec4 interior = (satInteriorBelow(sat, origin, hi, size) - satInteriorBelow(sat, origin, vec2(lo.x, hi.y), size))
                  - (satInteriorBelow(sat, origin, vec2(hi.x, lo.y), size) - satInteriorBelow(sat, origin, lo, size));
    vec2 extent = hi - lo;
    vec4 firstRow = extent.y * (satEdge(sat, origin, hi.x, size.x, 0) - satEdge(sat, origin, lo.x, size.x, 0));
    vec4 firstColumn = extent.x * (satEdge(sat, origin, hi.y, size.y, 1) - satEdge(sat, origin, lo.y, size.y, 1));
    vec4 a = texelFetch(sat, origin, 0);
    return interior + firstRow + firstColumn + (extent.x * extent.y) * a;
}

// Mean of the moments over the box of size boxSize (>= 1 texel, fractional allowed) centred
// at `center`, clipped to the map [0, size]. Partially covered texels count with the
// fraction covered.
vec4 satBoxAverage(sampler2D sat, vec2 center, vec2 boxSize)
{
    ivec2 size = textureSize(sat, 0) / ivec2(2, 1);  // the map: the table has two texels per entry
    vec2 lo = clamp(center - 0.5 * boxSize, vec2(0.0), vec2(size));
    vec2 hi = clamp(center + 0.5 * boxSize, vec2(0.0), vec2(size));
    vec2 extent = hi - lo;
    // A box that misses the map entirely has no area: return 0, not 0 / 0.
    if (extent.x <= 0.0 || extent.y <= 0.0)
        return vec4(0.0);
    // The tiles the box overlaps (with a non-empty part): [tileLo, tileHi].
    ivec2 tileLo = ivec2(floor(lo / float(SAT_TILE)));
    ivec2 tileHi = ivec2(ceil(hi / float(SAT_TILE))) - 1;
    vec4 sum = vec4(0.0);
    for (int ty = tileLo.y; ty <= tileHi.y; ++ty)
        for (int tx = tileLo.x; tx <= tileHi.x; ++tx) {
            ivec2 origin = ivec2(tx, ty) * SAT_TILE;
            ivec2 tileSize = min(ivec2(SAT_TILE), size - origin);
            vec2 partLo = max(lo - vec2(origin), vec2(0.0));
            vec2 partHi = min(hi - vec2(origin), vec2(tileSize));
            if (partHi.x > partLo.x && partHi.y > partLo.y)
                sum += satTileSum(sat, origin, tileSize, partLo, partHi);
        }
    return sum / (extent.x * extent.y);
}
