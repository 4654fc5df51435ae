// techniques/evsm2.glsl: exponential variance shadow maps, positive warp (Lauritzen 2008).
//   z'       2 z − 1 ∈ [−1, 1]
//   warp     w(z) = e^{c z'}, c = min(positiveExponent, 42): e^{2c} stays below float32's
//            3.4·10³⁸ (ln ≈ 88.7), so the stored second moment never overflows
//   stored   (w, w²), filtered linearly
//   p        Chebyshev on the warped moments at w(z_f), σ² ≥ minVariance · (c · w(z_f))²
//            (the floor scales with the warp's slope, so it means the same depth everywhere)
//   G = 1 − reduce(p, bleedReduction)
// The warp makes stacked occluders' variance tiny next to the receiver's distance: less bleeding.
#include "techniques/evsm_common.glsl"

#ifndef SL_PROBE
uniform float uPositiveExponent;
uniform float uMinVariance;
uniform float uBleedReduction;
#endif

float evsm2ShadowIntensity(vec2 m, float zf, float cPositive, float minVariance, float bleed) {
    float c = min(cPositive, 42.0);
    return 1.0 - reduceLightBleeding(evsmPositiveLit(m, zf, c, minVariance), bleed);
}

#ifndef SL_PROBE
float shadowIntensityEvsm2(ShadowQuery q) {
    return evsm2ShadowIntensity(filteredMap(q.map, 0, q.uv).xy, q.zf, uPositiveExponent,
                                uMinVariance, uBleedReduction);
}
#define SL_SHADOW_INTENSITY shadowIntensityEvsm2
#endif
