// FRAGILE VARIANT (tests/test_numerics_fragile.cpp): the pre-fix reference sat_lookup.glsl,
// reading the plain float32 table of naive_sat/sat.comp. Do not use as a solution.
// sat_lookup.glsl: box average of the moment map from its summed-area table.
// Reference solution. Stage contract: docs/stage_contract.md.
//
// Included by the lighting pass (and by shaders/sat_resolve.comp) when the filter is a SAT.
// `sat` is the table written by sat.comp: S(i, j) = sum of the moments of all texels (x, y)
// with x <= i and y <= j. It is bound with nearest filtering and read with texelFetch.
// Texel i covers [i, i + 1); box centres and sizes are in texel units.

// S at integer table index i, with S = 0 at index -1 (the empty sum left of / below the map).
vec4 satFetch(sampler2D sat, ivec2 i)
{
    vec4 s = texelFetch(sat, max(i, ivec2(0)), 0);  // never fetch out of bounds
    return (i.x < 0 || i.y < 0) ? vec4(0.0) : s;
}

// Sum of the moment map over [0, e.x] × [0, e.y], for a corner e inside [0, size]².
// The integral of a piecewise-constant image is bilinear within each cell of the integer
// grid, so linear interpolation of S at e - 1 between integer indices is exact, also for
// fractional e: the box includes the fraction of the partially covered texel.
// The interpolation is done by hand in float32. Hardware linear filtering would be exact in
// theory, but GPUs compute its weights in fixed point with ~8 fractional bits; S grows to
// ~(width · height) · moment, so a 1/256 weight error would cost a fraction of a whole
// column sum. (The contract binds the table with nearest filtering anyway.)
vec4 satSumBelow(sampler2D sat, vec2 e, ivec2 size)
{
    vec2 t = e - 1.0;
    // Lower corner of the interpolation cell, kept in [-1, size - 2] so that i + 1 is still
    // a table index; t = size - 1 (the far edge) then gets weight f = 1.
    ivec2 i = clamp(ivec2(floor(t)), ivec2(-1), max(size - 2, ivec2(-1)));
    vec2 f = t - vec2(i);
    vec4 s00 = satFetch(sat, i);
    vec4 s10 = satFetch(sat, i + ivec2(1, 0));
    vec4 s01 = satFetch(sat, i + ivec2(0, 1));
    vec4 s11 = satFetch(sat, i + ivec2(1, 1));
    return mix(mix(s00, s10, f.x), mix(s01, s11, f.x), f.y);
}

// Mean of the moments over the box of size boxSize (>= 1 texel, fractional allowed) centred
// at `center`, clipped to the map [0, size]. Partially covered texels count with the
// fraction covered. Four corner sums give the box sum by inclusion-exclusion:
//     sum = S(x1, y1) - S(x0, y1) - S(x1, y0) + S(x0, y0).
// Precision: the corner sums are large (up to width · height) and nearly cancel, so float32
// loses about log2(width · height / box area) bits here. sat.comp may subtract an offset
// from the moments to keep S small; undo it below if so (this table stores plain sums).
vec4 satBoxAverage(sampler2D sat, vec2 center, vec2 boxSize)
{
    ivec2 size = textureSize(sat, 0) / ivec2(2, 1);  // the map: the table has two texels per entry
    vec2 lo = clamp(center - 0.5 * boxSize, vec2(0.0), vec2(size));
    vec2 hi = clamp(center + 0.5 * boxSize, vec2(0.0), vec2(size));
    vec2 extent = hi - lo;
    // A box that misses the map entirely has no area: return 0, not 0 / 0.
    if (extent.x <= 0.0 || extent.y <= 0.0)
        return vec4(0.0);
    vec4 sum = (satSumBelow(sat, hi, size) - satSumBelow(sat, vec2(lo.x, hi.y), size))
             - (satSumBelow(sat, vec2(hi.x, lo.y), size) - satSumBelow(sat, lo, size));
    return sum / (extent.x * extent.y);
}
