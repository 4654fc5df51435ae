// MUTANT: per-pixel box: a directional light's penumbra divided by the blocker's depth as a spot light's is (the perspective flag ignored)
// sat_lookup.glsl: box average of the moment map from its summed-area table.
//
// Included by the lighting pass (and by shaders/sat_resolve.comp) when the filter is a SAT.
// `sat` is the table T written by sat.comp, bound with nearest filtering, read with texelFetch.
// Texel i covers [i, i + 1); box centres and sizes are in texel units.
//
// T is stored with an offset (see sat.comp): with a = m(0, 0), for x, y >= 1
//     T(x, y) = Σ_{1<=i<=x, 1<=j<=y} (m(i,j) - m(0,j) - m(i,0) + a)      ("interior")
//     A(x) = T(x, 0) = Σ_{1<=i<=x} (m(i,0) - a),   B(y) = T(0, y) = Σ_{1<=j<=y} (m(0,j) - a),
// and the plain table follows as (take T(x, y) = 0 if x or y is <= 0, A(x) = 0 for x <= 0,
// B(y) = 0 for y <= 0; this also gives S(-1, ·) = S(·, -1) = 0):
//     S(x, y) = T(x, y) + (y + 1)·A(x) + (x + 1)·B(y) + (x + 1)·(y + 1)·a.
// In the four-corner difference the last three terms collapse to exact closed forms (below),
// so only the (small) sums of differences are subtracted. The error left is ~u·|T| at the
// box's corners: 0 on smooth depth, ~1e-4 per occluder-filled 100² texels below-left of the
// box; 10-40× below a plain float32 table's on 512²-4096² maps (docs/numerics.md).

// Interior part T at integer index i; 0 on the first row / column and left of / below the map.
vec4 satInterior(sampler2D sat, ivec2 i)
{
    vec4 t = texelFetch(sat, max(i, ivec2(0)), 0);  // never fetch out of bounds
    return (i.x <= 0 || i.y <= 0) ? vec4(0.0) : t;
}

// A (axis 0: the first row) or B (axis 1: the first column), linearly interpolated at
// index t = e - 1 for an edge position e in [0, size]; 0 at indices <= 0.
vec4 satEdge(sampler2D sat, float e, int size, int axis)
{
    float t = e - 1.0;
    int i = clamp(int(floor(t)), -1, max(size - 2, -1));
    float f = t - float(i);
    ivec2 i0 = axis == 0 ? ivec2(max(i, 0), 0) : ivec2(0, max(i, 0));
    ivec2 i1 = axis == 0 ? ivec2(i + 1, 0) : ivec2(0, i + 1);
    vec4 v0 = i <= 0 ? vec4(0.0) : texelFetch(sat, i0, 0);
    vec4 v1 = i + 1 <= 0 ? vec4(0.0) : texelFetch(sat, i1, 0);
    return mix(v0, v1, f);
}

// Interior part of the sum over [0, e.x] × [0, e.y], for a corner e inside [0, size]².
// The integral of a piecewise-constant image is bilinear within each cell of the integer
// grid, so linear interpolation at e - 1 between integer indices is exact, also for
// fractional e: the box includes the fraction of the partially covered texel.
// Interpolated by hand: hardware filtering computes its weights with ~8 fractional bits.
vec4 satInteriorBelow(sampler2D sat, vec2 e, ivec2 size)
{
    vec2 t = e - 1.0;
    // Lower corner of the interpolation cell, kept in [-1, size - 2] so that i + 1 is still
    // a table index; t = size - 1 (the far edge) then gets weight f = 1.
    ivec2 i = clamp(ivec2(floor(t)), ivec2(-1), max(size - 2, ivec2(-1)));
    vec2 f = t - vec2(i);
    vec4 s00 = satInterior(sat, i);
    vec4 s10 = satInterior(sat, i + ivec2(1, 0));
    vec4 s01 = satInterior(sat, i + ivec2(0, 1));
    vec4 s11 = satInterior(sat, i + ivec2(1, 1));
    return mix(mix(s00, s10, f.x), mix(s01, s11, f.x), f.y);
}

// Mean of the moments over the box of size boxSize (>= 1 texel, fractional allowed) centred
// at `center`, clipped to the map [0, size]. Partially covered texels count with the
// fraction covered. The box sum by inclusion-exclusion, S(hi) - S(lo.x, hi.y) - S(hi.x, lo.y)
// + S(lo), term by term of S above (with e = t + 1 the interpolation position):
//     interior:        the same four-corner difference of T;
//     (y + 1)·A(x):    (hi.y - lo.y)·(A(hi.x) - A(lo.x));
//     (x + 1)·B(y):    (hi.x - lo.x)·(B(hi.y) - B(lo.y));
//     (x+1)(y+1)·a:    area·a, so a is added to the mean exactly.
vec4 satBoxAverage(sampler2D sat, vec2 center, vec2 boxSize)
{
    ivec2 size = textureSize(sat, 0) / ivec2(2, 1);  // the map: the table has two texels per entry
    vec2 lo = clamp(center - 0.5 * boxSize, vec2(0.0), vec2(size));
    vec2 hi = clamp(center + 0.5 * boxSize, vec2(0.0), vec2(size));
    vec2 extent = hi - lo;
    // A box that misses the map entirely has no area: return 0, not 0 / 0.
    if (extent.x <= 0.0 || extent.y <= 0.0)
        return vec4(0.0);
    vec4 interior = (satInteriorBelow(sat, hi, size) - satInteriorBelow(sat, vec2(lo.x, hi.y), size))
                  - (satInteriorBelow(sat, vec2(hi.x, lo.y), size) - satInteriorBelow(sat, lo, size));
    vec4 firstRow = extent.y * (satEdge(sat, hi.x, size.x, 0) - satEdge(sat, lo.x, size.x, 0));
    vec4 firstColumn = extent.x * (satEdge(sat, hi.y, size.y, 1) - satEdge(sat, lo.y, size.y, 1));
    vec4 a = texelFetch(sat, ivec2(0), 0);
    return (interior + firstRow + firstColumn) / (extent.x * extent.y) + a;
}

// The box each pixel filters with, in map texels: the width of the penumbra a receiver at
// relative depth zr gets from the blockers in front of it (contact hardening). Two steps, both
// from the table in a constant number of reads:
//   1. blocker search, variance soft shadow mapping (Yang et al. 2010): over the search box,
//      mean μ = b1 and variance σ² = b2 − μ². Chebyshev's bound p = σ² / (σ² + (zr − μ)²)
//      estimates the fraction of the box that lies at or behind the receiver (unoccluded);
//      the box's mean is p·zr + (1 − p)·z_b, so the blockers' mean depth is
//      z_b = (μ − p·zr) / (1 − p).
//   2. penumbra by similar triangles (PCSS, Fernando 2005) with world depths d along the
//      light's axis: w = lightTexels·(d_r − d_b) / d_b (perspective), lightTexels·(d_r − d_b)
//      (orthographic), clamped to kernelRange.
// The box must not jump where the estimate is unsure: a blocker share 1 − p near 0 places its
// blockers anywhere (z_b is a ratio of two vanishing numbers), so the penumbra fades in over
// the first 5 % of share, from the smallest box. Then the box is continuous in the moments,
// and two solutions whose tables round differently choose nearly the same box.
float satKernelTexels(sampler2D sat, vec2 center, float searchTexels, float zr, vec2 depthRange,
                      float lightTexels, bool perspective, vec2 kernelRange)
{
    vec4 b = satBoxAverage(sat, center, vec2(searchTexels));
    float mu = b.x;
    // σ² is a difference of nearly equal floats (b2 and μ²): a floor keeps a flat box from
    // giving 0 / 0 below, and is far below any variance a real depth step makes.
    float variance = max(b.y - mu * mu, 1e-7);
    // The receiver in front of (or at) the mean: Chebyshev says nothing lies in front of it.
    if (zr <= mu)
        return kernelRange.x;
    float d = zr - mu;
    float p = variance / (variance + d * d);
    float share = 1.0 - p;  // the blockers' share of the search box
    // No blockers to speak of (and no 0 / 0 below); the fade makes this the limit anyway.
    if (share < 1e-6)
        return kernelRange.x;
    float zb = clamp((mu - p * zr) / share, 0.0, zr);
    float dr = mix(depthRange.x, depthRange.y, zr);
    float db = mix(depthRange.x, depthRange.y, zb);
    // Perspective: the emitter's width scales by (d_r − d_b) / d_b from blocker to receiver;
    // d_b is kept off 0 (a blocker on the light itself).
    float w = lightTexels * (dr - db) / max(db, 1e-4 * depthRange.y);
    return mix(kernelRange.x, clamp(w, kernelRange.x, kernelRange.y), clamp(share / 0.05, 0.0, 1.0));
}
