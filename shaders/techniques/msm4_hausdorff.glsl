// techniques/msm4_hausdorff.glsl: Hausdorff 4MSM (Peters & Klein 2015, the variant for depths
// known to lie in [0, 1]). The Hamburger bound assumes depths anywhere on ℝ; when its support
// points z2, z3 fall inside [0, 1] it is also the sharpest bound on [0, 1], and G is the same.
// Otherwise the sharpest lower bound on [0, 1] has support {0, z_f, x, 1}: the polynomial
// q(z) = z (1 − z)(z − z_f)(z − x) vanishes on the support, so E[q] = 0 gives
//   x = (−b4 + (1 + z_f) b3 − z_f b2) / (−b3 + (1 + z_f) b2 − z_f b1),
// and the weights solve the 4×4 Vandermonde system with moments (1, b1, b2, b3). G is the weight
// in front of z_f: w(0) + [x < z_f] w(x). Bias α toward (½, ½, ½, ½), as msm.glsl. The
// Hamburger case is the solution's momentShadowIntensity (msm.glsl, same α); the roots come from
// techniques/msm_hamburger.glsl, which solves the msm stage: instructor kit only.
#include "techniques/msm_hamburger.glsl"  // instructor kit only (it solves the msm stage)

float msm4HausdorffShadowIntensity(vec4 unbiased, float zf, float alpha) {
    vec4 b = mix(unbiased, vec4(0.5), alpha);
    vec2 z = msmRoots(b, zf);
    if (z.x >= 0.0 && z.y <= 1.0) return momentShadowIntensity(unbiased, zf);
    float den = -b.z + (1.0 + zf) * b.y - zf * b.x;
    float num = -b.w + (1.0 + zf) * b.z - zf * b.y;
    if (abs(den) < 1e-12) return momentShadowIntensity(unbiased, zf);
    float x = clamp(num / den, 0.0, 1.0);
    // Weight of node 0: E[(z − zf)(z − x)(z − 1)] / ((0 − zf)(0 − x)(0 − 1)).
    float e0 = b.z - (zf + x + 1.0) * b.y + (zf * x + zf + x) * b.x - zf * x;
    float w0 = (zf * x > 1e-12) ? e0 / (-zf * x) : 0.0;
    // Weight of node x: E[z (z − zf)(z − 1)] / (x (x − zf)(x − 1)).
    float ex = b.z - (zf + 1.0) * b.y + zf * b.x;
    float dx = x * (x - zf) * (x - 1.0);
    float wx = abs(dx) > 1e-12 ? ex / dx : 0.0;
    return clamp(w0 + (x < zf ? wx : 0.0), 0.0, 1.0);
}

#ifndef SL_PROBE
float shadowIntensityMsm4Hausdorff(ShadowQuery q) {
    return msm4HausdorffShadowIntensity(filteredMap(q.map, 0, q.uv), q.zf, uMomentBias);
}
#define SL_SHADOW_INTENSITY shadowIntensityMsm4Hausdorff
#endif
