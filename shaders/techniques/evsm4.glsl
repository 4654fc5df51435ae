// techniques/evsm4.glsl: exponential variance shadow maps with both warps (Lauritzen 2008).
//   stored   (e^{c+ z'}, e^{2c+ z'}, −e^{−c− z'}, e^{−2c− z'}), z' = 2z − 1, c± ≤ 42 (float32)
//   p±       Chebyshev on each warped pair at the receiver's warped depth (evsm2.glsl); the
//            negative warp is increasing too (−e^{−c z'}), so both are upper bounds of the lit
//            fraction and the smaller is kept: p = min(p+, p−)
//   G = 1 − reduce(p, bleedReduction)
// The negative warp removes the dark halos the positive one leaves where the receiver is close
// behind the occluder (non-planar receivers).
#include "techniques/evsm_common.glsl"

#ifndef SL_PROBE
uniform float uPositiveExponent;
uniform float uNegativeExponent;
uniform float uMinVariance;
uniform float uBleedReduction;
#endif

float evsm4ShadowIntensity(vec4 m, float zf, float cPositive, float cNegative, float minVariance,
                           float bleed) {
    float cp = min(cPositive, 42.0);
    float cn = min(cNegative, 42.0);
    float pPos = evsmPositiveLit(m.xy, zf, cp, minVariance);
    float wn = -exp(-cn * (2.0 * zf - 1.0));
    float scale = cn * wn;
    float pNeg = chebyshevUpperBound(m.zw, wn, minVariance * scale * scale);
    return 1.0 - reduceLightBleeding(min(pPos, pNeg), bleed);
}

#ifndef SL_PROBE
float shadowIntensityEvsm4(ShadowQuery q) {
    return evsm4ShadowIntensity(filteredMap(q.map, 0, q.uv), q.zf, uPositiveExponent,
                                uNegativeExponent, uMinVariance, uBleedReduction);
}
#define SL_SHADOW_INTENSITY shadowIntensityEvsm4
#endif
