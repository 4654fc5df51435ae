// techniques/pcf.glsl: percentage-closer filtering (Reeves et al. 1987): filter the results of
// the depth tests, not the depths. The kernel is the scene's filter, evaluated here, so that
// PCF is the *exact filtered visibility* the moment techniques approximate with the same kernel:
//   none      bilinear PCF: the 4 tests around uv, weighted bilinearly
//   gaussian  G = Σ_b β_b Σ_{dx,dy} w_|dx| w_|dy| test(t_b + (dx, dy)): the moment filter's
//             weights w (uGaussianWeights, the same buffer as gaussian_blur.comp) at each of the
//             4 bilinear taps β_b, since the moment map is filtered on texels then read bilinearly
//   sat       the box of uSatKernel texels centred at uv, partial texels by coverage
// test(t) = 1 if z_f − bias > z_map(t) (bias as in hard.glsl; one bias for the whole kernel).
#ifndef SL_PROBE
uniform float uConstantBias;
uniform float uSlopeBias;
uniform int uGaussianRadius;
uniform float uGaussianWeights[65];
#endif

#ifndef SL_PROBE
float pcfTest(ShadowQuery q, ivec2 t, float zBiased) {
    return zBiased > mapDepth(q.map, t) ? 1.0 : 0.0;
}

#if defined(SL_FILTER_GAUSSIAN)
float pcfKernelAt(ShadowQuery q, ivec2 t, float zb) {
    float sum = 0.0;
    int r = uGaussianRadius;
    for (int dy = -r; dy <= r; ++dy) {
        float row = 0.0;
        for (int dx = -r; dx <= r; ++dx)
            row += uGaussianWeights[abs(dx)] * pcfTest(q, t + ivec2(dx, dy), zb);
        sum += uGaussianWeights[abs(dy)] * row;
    }
    return sum;
}
#endif

float shadowIntensityPcf(ShadowQuery q) {
    float zb = q.zf - receiverBias(q, uConstantBias, uSlopeBias);
#if defined(SL_FILTER_SAT)
    vec2 c = q.uv * uMapTexels;
    vec2 lo = clamp(c - 0.5 * uSatKernel, vec2(0.0), uMapTexels);
    vec2 hi = clamp(c + 0.5 * uSatKernel, vec2(0.0), uMapTexels);
    float sum = 0.0;
    for (int y = int(floor(lo.y)); y < int(ceil(hi.y)); ++y) {
        float cy = min(hi.y, float(y + 1)) - max(lo.y, float(y));
        for (int x = int(floor(lo.x)); x < int(ceil(hi.x)); ++x) {
            float cx = min(hi.x, float(x + 1)) - max(lo.x, float(x));
            sum += cx * cy * pcfTest(q, ivec2(x, y), zb);
        }
    }
    return clamp(sum / max((hi.x - lo.x) * (hi.y - lo.y), 1e-12), 0.0, 1.0);
#else
    // Bilinear taps, as GL_LINEAR reads a map with texel centres at (i + ½) / size.
    vec2 p = q.uv * uMapTexels - 0.5;
    ivec2 t = ivec2(floor(p));
    vec2 f = p - vec2(t);
    vec4 g;
#if defined(SL_FILTER_GAUSSIAN)
    g = vec4(pcfKernelAt(q, t, zb), pcfKernelAt(q, t + ivec2(1, 0), zb),
             pcfKernelAt(q, t + ivec2(0, 1), zb), pcfKernelAt(q, t + ivec2(1, 1), zb));
#else
    g = vec4(pcfTest(q, t, zb), pcfTest(q, t + ivec2(1, 0), zb), pcfTest(q, t + ivec2(0, 1), zb),
             pcfTest(q, t + ivec2(1, 1), zb));
#endif
    // The weights sum to 1 only up to rounding: keep G in [0, 1] (lighting flags G > 1).
    return clamp(mix(mix(g.x, g.y, f.x), mix(g.z, g.w, f.x), f.y), 0.0, 1.0);
#endif
}
#define SL_SHADOW_INTENSITY shadowIntensityPcf
#endif
