// ALTERNATIVE: written from the student kit alone: corners interpolated by hand in double at index e - 1 (32 fetches); satKernelTexels as the contract's steps
// sat_lookup.glsl: box average of the moment map from its summed-area table, and the box
// each pixel chooses from its situation.
// Stage contract: docs/stage_contract.md (the part that concerns this file is repeated here).
//
// Included by the lighting pass and by shaders/sat_resolve.comp when the filter is a
// summed-area table (SAT). Do not write a #version line: the framework prepends
// `#version 450 core`.
//
// vec4 satBoxAverage(sampler2D sat, vec2 center, vec2 boxSize)
//   sat      the table written by your sat.comp: S(i, j) = sum of the moments of all texels
//            (x, y) with x <= i and y <= j, entry (i, j) in the two texels (2i, j) and
//            (2i + 1, j) as your sat.comp stored it. Bound with nearest filtering: read it
//            with texelFetch(sat, ivec2(2 * i, j), 0) and texelFetch(sat, ivec2(2 * i + 1, j), 0).
//            textureSize(sat, 0) is (2W, H) for a W × H map.
//   center   centre of the box in texel units (texel i covers [i, i + 1)).
//   boxSize  its width and height in texels; fractional sizes are allowed (>= 1).
//   returns  the mean of the moment map over the box clipped to the map, partially covered
//            texels weighted by the fraction of them that the box covers.
//            With S(-1) = 0, the sum of all texels left of a box edge at position e is S
//            linearly interpolated at index e - 1.
//
// Read the entries back the way your sat.comp stored them: the two files are graded
// together, on the box averages this function returns.
//
// Stub value: until implemented, the function returns -1 in every channel, which the
// framework reports as "not implemented yet" and previews in magenta. A correct solution
// never returns a negative moment.

// The table (sat.comp): entry (i, j) = hi at (2i, j) + lo at (2i + 1, j), a double sum.
dvec4 satEntry(sampler2D sat, int i, int j)
{
    dvec4 hi = dvec4(texelFetch(sat, ivec2(2 * i, j), 0));
    dvec4 lo = dvec4(texelFetch(sat, ivec2(2 * i + 1, j), 0));
    return hi + lo;
}

// The sum of the map over [0, e.x] x [0, e.y], 0 <= e <= size: S bilinearly interpolated at
// the index e - 1, with S = 0 at index -1. Always four entries (weights 0 where unused).
dvec4 satCornerSum(sampler2D sat, dvec2 e, ivec2 size)
{
    dvec2 t  = e - 1.0LF;                        // in [-1, size - 1]
    dvec2 t0 = floor(t);
    dvec2 f  = t - t0;                           // in [0, 1)
    ivec2 i0 = ivec2(t0);                        // in [-1, size - 1]
    ivec2 i1 = i0 + 1;                           // in [0, size]: weight 0 when = size

    // Entries at index -1 are 0; entries at index size only ever get weight 0.
    bool x0ok = i0.x >= 0, y0ok = i0.y >= 0;
    bool x1ok = i1.x < size.x, y1ok = i1.y < size.y;
    ivec2 c0 = clamp(i0, ivec2(0), size - 1);
    ivec2 c1 = clamp(i1, ivec2(0), size - 1);

    dvec4 s00 = satEntry(sat, c0.x, c0.y);
    dvec4 s10 = satEntry(sat, c1.x, c0.y);
    dvec4 s01 = satEntry(sat, c0.x, c1.y);
    dvec4 s11 = satEntry(sat, c1.x, c1.y);
    if (!(x0ok && y0ok)) s00 = dvec4(0.0);
    if (!(x1ok && y0ok)) s10 = dvec4(0.0);
    if (!(x0ok && y1ok)) s01 = dvec4(0.0);
    if (!(x1ok && y1ok)) s11 = dvec4(0.0);

    dvec4 bottom = s00 + (s10 - s00) * f.x;
    dvec4 top    = s01 + (s11 - s01) * f.x;
    return bottom + (top - bottom) * f.y;
}

vec4 satBoxAverage(sampler2D sat, vec2 center, vec2 boxSize)
{
    ivec2 tsize = textureSize(sat, 0);
    ivec2 size  = ivec2(tsize.x / 2, tsize.y);   // the moment map's W x H
    dvec2 dsize = dvec2(size);

    dvec2 c    = dvec2(center);
    dvec2 hb   = dvec2(boxSize) * 0.5LF;
    dvec2 lo   = clamp(c - hb, dvec2(0.0), dsize);
    dvec2 hi   = clamp(c + hb, dvec2(0.0), dsize);
    dvec2 ext  = hi - lo;
    double area = ext.x * ext.y;

    dvec4 s11 = satCornerSum(sat, hi, size);
    dvec4 s01 = satCornerSum(sat, dvec2(lo.x, hi.y), size);
    dvec4 s10 = satCornerSum(sat, dvec2(hi.x, lo.y), size);
    dvec4 s00 = satCornerSum(sat, lo, size);
    dvec4 boxSum = (s11 - s01) - (s10 - s00);

    // A box that misses the map entirely has no area: return 0 (never 0 / 0), the value
    // `probe sat-lookup` expects there.
    if (!(area > 0.0LF))
        return vec4(0.0);
    return vec4(boxSum / area);
}

// float satKernelTexels(sampler2D sat, vec2 center, float searchTexels, float zr,
//                       vec2 depthRange, float lightTexels, bool perspective, vec2 kernelRange)
//   The width, in map texels, of the box the lighting pass filters this pixel with, when the
//   scene asks for a per-pixel kernel (filter "kernel": "per-pixel"): the penumbra that the
//   blockers in front of the receiver cast, sharp where they touch it, wide far away.
//   sat          the table, as for satBoxAverage
//   center       the receiver's position in the map, texel units
//   searchTexels the width of the box to search for blockers in (the framework's choice: the
//                penumbra a blocker at the near plane would cast, clamped)
//   zr           the receiver's relative depth (the scene's depth bias already subtracted)
//   depthRange   (near, far): relative depth z lies at world depth near + z·(far − near)
//                along the light's axis
//   lightTexels  the light's size in map texels at the receiver: perspective (spot) lights,
//                the emitter's width; orthographic (directional) ones, per world unit of
//                blocker–receiver distance
//   perspective  true for a spot light
//   kernelRange  (smallest, largest) box the result is clamped to
//   returns      the penumbra width w in texels, clamped to kernelRange; kernelRange.x where
//                nothing lies in front of the receiver
//
// Stub value: until implemented, it returns -1; the lighting pass then hatches the pixel in
// magenta and the renderer names this function. A correct solution never returns less
// than kernelRange.x.

float satKernelTexels(sampler2D sat, vec2 center, float searchTexels, float zr, vec2 depthRange,
                      float lightTexels, bool perspective, vec2 kernelRange)
{
    // 1. Blocker search (variance soft shadow mapping): mean and variance over the search box.
    vec4 m = satBoxAverage(sat, center, vec2(searchTexels));
    float mu = m.x;
    float variance = max(m.y - mu * mu, 1e-7);
    if (zr <= mu)
        return kernelRange.x;                    // nothing in front of the receiver

    // 2. Chebyshev: p = share at or behind the receiver, s = blockers' share.
    float t = zr - mu;
    float p = variance / (variance + t * t);
    float s = 1.0 - p;
    if (s < 1e-6)
        return kernelRange.x;

    // 3. Blockers' mean depth from mu = p zr + s zb, clamped to [0, zr].
    float zb = clamp((mu - p * zr) / s, 0.0, zr);

    // 4. Penumbra by similar triangles, world depths along the light's axis.
    float near = depthRange.x, far = depthRange.y;
    float dr = near + zr * (far - near);
    float db = near + zb * (far - near);
    float w = perspective ? lightTexels * (dr - db) / max(db, 1e-4 * far)
                          : lightTexels * (dr - db);

    // 5. Fade in over the first 5 % of blockers' share.
    return mix(kernelRange.x, clamp(w, kernelRange.x, kernelRange.y), clamp(s / 0.05, 0.0, 1.0));
}
