// techniques/vsm.glsl: variance shadow maps (Donnelly & Lauritzen 2006).
//   stored   (z, z²), filtered linearly (Gaussian or SAT box): (μ, μ₂) = the kernel's moments
//   σ²       max(μ₂ − μ², minVariance): the floor keeps flat regions from dividing by ~0
//   p_max    σ² / (σ² + (z_f − μ)²) if z_f > μ, else 1: the one-sided Chebyshev (Cantelli)
//            inequality, an upper bound of the lit fraction P(z ≥ z_f)
//   reduce   lit fractions below bleedReduction become 0, the rest rescale to [0, 1]: cuts the
//            light bleeding of stacked occluders at the cost of thinner penumbrae
//   G = 1 − reduce(p_max)
// With bleedReduction = 0 and minVariance ≈ 0, 1 − G ≥ the exact filtered visibility (PCF with
// the same kernel): tests/test_technique_renders.cpp (TechniqueBounds) checks it per pixel.
#ifndef SL_PROBE
uniform float uMinVariance;
uniform float uBleedReduction;
#endif

float vsmShadowIntensity(vec2 m, float zf, float minVariance, float bleedReduction) {
    float pMax = chebyshevUpperBound(m, zf, minVariance);
    return 1.0 - reduceLightBleeding(pMax, bleedReduction);
}

#ifndef SL_PROBE
float shadowIntensityVsm(ShadowQuery q) {
    return vsmShadowIntensity(filteredMap(q.map, 0, q.uv).xy, q.zf, uMinVariance, uBleedReduction);
}
#define SL_SHADOW_INTENSITY shadowIntensityVsm
#endif
