// sat_lookup.glsl: box average of the moment map from its summed-area table.
// Reference solution. Stage contract: docs/stage_contract.md.
//
// Included by the lighting pass (and by shaders/sat_resolve.comp) when the filter is a SAT.
// `sat` is the table written by sat.comp, bound with nearest filtering, read with texelFetch:
// 2W × H texels for a W × H map, entry (x, y) = S(x, y) = Σ_{i <= x, j <= y} m(i, j) stored as
// the float nearest it at (2x, y) plus the float nearest the rest at (2x + 1, y) (sat.comp).
// Texel i covers [i, i + 1); box centres and sizes are in texel units.
//
// The box sum is the four-corner difference of S, each corner S interpolated bilinearly
// between four entries: 16 entries (32 texels) for any box, so the cost does not grow with the
// box (docs/performance.md, "SAT lookup"). Sums, interpolation and differences are in double:
// entries reach W·H, and a 1-texel box is a difference of two such numbers. Error: ~1e-7 for
// any box on maps up to 4096² (docs/numerics.md).

// S at entry i in double; 0 at index -1 (the zero border left of and below the map).
dvec4 satEntry(sampler2D sat, ivec2 i)
{
    ivec2 t = ivec2(2, 1) * max(i, ivec2(0));  // never fetch out of bounds
    dvec4 s = dvec4(texelFetch(sat, t, 0)) + dvec4(texelFetch(sat, t + ivec2(1, 0), 0));
    return (i.x < 0 || i.y < 0) ? dvec4(0.0) : s;
}

// The sum over [0, e.x] × [0, e.y], for a corner e inside [0, size]²: S at e - 1. The integral
// of a piecewise-constant image is bilinear within each cell of the integer grid, so linear
// interpolation between integer indices is exact, also for fractional e: the box includes the
// fraction of a partially covered texel. By hand: hardware filtering has ~8 fractional bits.
dvec4 satBelow(sampler2D sat, vec2 e, ivec2 size)
{
    dvec2 t = dvec2(e) - 1.0;
    // Lower corner of the interpolation cell, kept in [-1, size - 2] so that i + 1 is still
    // a table index; t = size - 1 (the far edge) then gets weight f = 1.
    ivec2 i = clamp(ivec2(floor(t)), ivec2(-1), max(size - 2, ivec2(-1)));
    dvec2 f = t - dvec2(i);
    dvec4 s00 = satEntry(sat, i);
    dvec4 s10 = satEntry(sat, i + ivec2(1, 0));
    dvec4 s01 = satEntry(sat, i + ivec2(0, 1));
    dvec4 s11 = satEntry(sat, i + ivec2(1, 1));
    return mix(mix(s00, s10, f.x), mix(s01, s11, f.x), f.y);
}

// Mean of the moments over the box of size boxSize (>= 1 texel, fractional allowed) centred
// at `center`, clipped to the map [0, size]. Partially covered texels count with the
// fraction covered.
vec4 satBoxAverage(sampler2D sat, vec2 center, vec2 boxSize)
{
    ivec2 size = textureSize(sat, 0) / ivec2(2, 1);  // the map's size: two texels per entry
    vec2 lo = clamp(center - 0.5 * boxSize, vec2(0.0), vec2(size));
    vec2 hi = clamp(center + 0.5 * boxSize, vec2(0.0), vec2(size));
    vec2 extent = hi - lo;
    // A box that misses the map entirely has no area: return 0, not 0 / 0.
    if (extent.x <= 0.0 || extent.y <= 0.0)
        return vec4(0.0);
    dvec4 sum = (satBelow(sat, hi, size) - satBelow(sat, vec2(lo.x, hi.y), size))
              - (satBelow(sat, vec2(hi.x, lo.y), size) - satBelow(sat, lo, size));
    return vec4(sum / (double(extent.x) * double(extent.y)));
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
    float w = lightTexels * (dr - db) / (perspective ? max(db, 1e-4 * depthRange.y) : 1.0);
    return mix(kernelRange.x, clamp(w, kernelRange.x, kernelRange.y), clamp(share / 0.05, 0.0, 1.0));
}
