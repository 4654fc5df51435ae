// techniques/esm.glsl: exponential shadow maps (Annen et al. 2008).
//   stored   m = e^{c (z − 1)}, filtered linearly: the kernel's mean of e^{c (z_occ − 1)}
//   lit      V = clamp(m · e^{−c (z_f − 1)}, 0, 1): e^{−c (z_f − z_occ)} for one occluder,
//            below 1 behind it, and over 1 (clamped: lit) for a receiver in front of the map
//   G = 1 − V
// The shift by −1 cancels in the product; it keeps every stored value in (e^{−c}, 1], so a
// summed-area table of a whole map stays finite (e^{c z} at c = 80 is 5.5·10³⁴ per texel and
// a 1024² sum of it would overflow float32). c = min(exponent, 80): e^{−c} stays a normal float.
// A larger c sharpens the test toward the hard one but lets a receiver barely behind its
// occluder (z_f − z_occ ≲ 1/c) be lit: the light leaks at contact.
#if !defined(SL_PROBE) || defined(SL_STORE_PASS)
uniform float uExponent;
#endif

float esmExponent(float c) { return min(c, 80.0); }

float esmShadowIntensity(float m, float zf, float c) {
    return 1.0 - clamp(m * exp(-c * (zf - 1.0)), 0.0, 1.0);
}

#if defined(SL_STORE_PASS)
vec4 techniqueStore(float z) { return vec4(exp(esmExponent(uExponent) * (z - 1.0)), 0.0, 0.0, 0.0); }
#elif !defined(SL_PROBE)
float shadowIntensityEsm(ShadowQuery q) {
    return esmShadowIntensity(filteredMap(q.map, 0, q.uv).x, q.zf, esmExponent(uExponent));
}
#define SL_SHADOW_INTENSITY shadowIntensityEsm
#endif
