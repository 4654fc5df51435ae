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

vec4 satBoxAverage(sampler2D sat, vec2 center, vec2 boxSize)
{
    // TODO: not implemented yet: satBoxAverage
    //  1. The box is [center - boxSize / 2, center + boxSize / 2]; clip it to [0, size].
    //  2. Write a helper that returns the sum of the map over [0, e.x] × [0, e.y]: S at the
    //     (fractional) index e - 1, interpolated bilinearly between the four table entries
    //     around it, where entries at index -1 are 0 (do not texelFetch outside the table).
    //     Interpolate by hand with texelFetch: hardware linear filtering computes its
    //     weights with only about 8 bits, far too few for sums this large.
    //  3. The box sum is the inclusion-exclusion of the four corner sums:
    //         S(x1, y1) - S(x0, y1) - S(x1, y0) + S(x0, y0).
    //  4. Divide by the clipped area; a box with no area left returns vec4(0).
    // Precision: the corners are sums of up to W·H moments, and a small box is the difference
    // of nearly equal ones: float32 is far too coarse for that (double is not).
    // Speed (docs/performance.md): the lighting pass calls this per pixel with boxes from 1 to
    // hundreds of texels; the point of the table is that the cost does not depend on the box
    // (16 entries, whatever its size). llvmpipe's SIMD lanes run both sides of every branch.
    return vec4(-1.0);
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
    // TODO: not implemented yet: satKernelTexels
    //  1. Blocker search: from the first two moments averaged over the search box, estimate
    //     the mean relative depth z_b of what lies in front of the receiver (the course's
    //     handout, "determine the amount of blur desired based on the pixel's environment";
    //     docs/handout.md names the estimate to use). docs/stage_contract.md fixes every
    //     guard, since the grade compares widths: what a receiver with nothing in front of it
    //     gets, the variance floor, the clamp of z_b to [0, zr], and how the box fades in
    //     with the blockers' share.
    //  2. Penumbra: similar triangles between the light, the blockers and the receiver, with
    //     world depths along the light's axis; then clamp.
    return -1.0;
}
