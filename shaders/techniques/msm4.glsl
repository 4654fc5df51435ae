// techniques/msm4.glsl: the assignment, Hamburger 4MSM (Peters & Klein 2015), entirely from the
// solution's stage files: the map holds computeMoments (moments.glsl), filtered by
// gaussian_blur.comp or read through sat.comp's table with satBoxAverage (sat_lookup.glsl),
// and G is momentShadowIntensity (msm.glsl) with the scene's moment bias uMomentBias.
#ifndef SL_PROBE
float shadowIntensityMsm4(ShadowQuery q) {
    return momentShadowIntensity(filteredMap(q.map, 0, q.uv), q.zf);
}
#define SL_SHADOW_INTENSITY shadowIntensityMsm4
#endif
