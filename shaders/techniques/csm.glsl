// techniques/csm.glsl: convolution shadow maps (Annen et al. 2007).
//   The shadow test H(z − d) (1: lit) as a Fourier series of a square wave on [−1, 1]:
//     H(t) ≈ ½ + Σ_{k=1..M} σ_k (2 / c_k) sin(c_k t),   c_k = π (2k − 1)
//   sin(c_k (z − d)) = sin(c_k z) cos(c_k d) − cos(c_k z) sin(c_k d), so storing
//   (cos c_k z, sin c_k z) per texel (2M channels, M/2 RGBA32F maps) and filtering them
//   linearly gives the filtered test at any receiver depth d.
//   σ_k = exp(−damping · (k / M)²)   damps the ringing (Gibbs) of the truncated series
//   d = z_f − offset                 the truncated step is ½ at t = 0: without the offset a
//                                    receiver would shadow itself by half
//   V = clamp(sharpen · (V − ½) + ½)  steepens the slow rise of the truncated step
//   G = 1 − V
#ifndef SL_PARAM_terms
#define SL_PARAM_terms 4  // the probe's; the lighting pass defines the scene's M
#endif
#define SL_CSM_TERMS SL_PARAM_terms
#define SL_CSM_LAYERS ((SL_CSM_TERMS + 1) / 2)

const float kPi = 3.14159265358979;

#ifndef SL_PROBE
uniform float uDamping;
uniform float uOffset;
uniform float uSharpen;
#endif

// layers[l] = (cos c_{2l+1} z, sin c_{2l+1} z, cos c_{2l+2} z, sin c_{2l+2} z), filtered.
float csmShadowIntensity(vec4 layers[SL_CSM_LAYERS], float zf, float damping, float offset,
                         float sharpen) {
    float d = zf - offset;
    float v = 0.5;
    for (int k = 1; k <= SL_CSM_TERMS; ++k) {
        float c = kPi * float(2 * k - 1);
        vec4 l = layers[(k - 1) / 2];
        vec2 cs = ((k - 1) % 2 == 0) ? l.xy : l.zw;  // (E cos c z, E sin c z)
        float sigma = exp(-damping * float(k * k) / float(SL_CSM_TERMS * SL_CSM_TERMS));
        v += sigma * (2.0 / c) * (cs.y * cos(c * d) - cs.x * sin(c * d));
    }
    return 1.0 - clamp(sharpen * (v - 0.5) + 0.5, 0.0, 1.0);
}

#ifndef SL_PROBE
float shadowIntensityCsm(ShadowQuery q) {
    vec4 layers[SL_CSM_LAYERS];
    for (int l = 0; l < SL_CSM_LAYERS; ++l) layers[l] = filteredMap(q.map, l, q.uv);
    return csmShadowIntensity(layers, q.zf, uDamping, uOffset, uSharpen);
}
#define SL_SHADOW_INTENSITY shadowIntensityCsm
#endif
