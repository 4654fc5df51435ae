// techniques/msm4.glsl: the assignment, Hamburger 4MSM (Peters & Klein 2015), entirely from the
// solution's stage files: the map holds computeMoments (moments.glsl), filtered by
// gaussian_blur.comp or read through sat.comp's table with satBoxAverage (sat_lookup.glsl),
// and G is momentShadowIntensity (msm.glsl) with the scene's moment bias uMomentBias.
// With a per-pixel SAT kernel (SL_SAT_PER_PIXEL, filter "kernel": "per-pixel"), each pixel's
// box is the solution's satKernelTexels (sat_lookup.glsl): a blocker search over the table,
// then the penumbra from the light's size.
#ifndef SL_PROBE
#ifdef SL_SAT_PER_PIXEL
uniform float uSatSearchTexels;  // largest blocker search box, texels
uniform float uSatMaxKernel;     // largest filter box, texels

float shadowIntensityMsm4(ShadowQuery q) {
    vec2 c = q.uv * uMapTexels;
    // Search as wide as the penumbra a blocker at the near plane would cast: no blocker can
    // reach the receiver from farther out.
    float search = clamp(penumbraWidth(q, q.depthRange.x) / q.texelWorld, 1.0, uSatSearchTexels);
    float kernel = satKernelTexels(uShadowMaps[q.map], c, search, q.zf, q.depthRange,
                                   q.lightSize / q.texelWorld, q.isSpot != 0,
                                   vec2(1.0, uSatMaxKernel));
    // satKernelTexels' stub (-1): the search box stands in, and G = -4 names the function
    // (noteLightingStubs), unless msm.glsl is a stub too (-1): that one is named first.
    bool stub = kernel == -1.0;
    float G = momentShadowIntensity(
        satBoxAverage(uShadowMaps[q.map], c, vec2(stub ? search : kernel)), q.zf);
    return stub && G != -1.0 ? -4.0 : G;
}
#else
float shadowIntensityMsm4(ShadowQuery q) {
    return momentShadowIntensity(filteredMap(q.map, 0, q.uv), q.zf);
}
#endif
#define SL_SHADOW_INTENSITY shadowIntensityMsm4
#endif
