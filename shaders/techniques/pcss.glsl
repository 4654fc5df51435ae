// techniques/pcss.glsl: percentage-closer soft shadows (Fernando 2005).
//   1. blocker search: the mean depth z_b of the stored depths in front of the receiver, over a
//      box as wide as the penumbra a blocker at the near plane would cast (≤ maxKernelTexels)
//   2. penumbra: w = lightSize · (d_r − d_b) / d_b (spot; directional: lightSize · (d_r − d_b)),
//      world units at the receiver, d = world depths along the light's axis
//   3. PCF over a box of w / texelWorld texels (bilinear taps on a 9 × 9 grid)
// Bias as in hard.glsl, for both the search and the filter. No blocker: G = 0.
#ifndef SL_PROBE
uniform float uConstantBias;
uniform float uSlopeBias;
uniform float uMaxKernelTexels;
#endif

#ifndef SL_PROBE
float pcssBilinearTest(ShadowQuery q, vec2 texelPos, float zb) {
    vec2 p = texelPos - 0.5;
    ivec2 t = ivec2(floor(p));
    vec2 f = p - vec2(t);
    vec4 g = vec4(zb > mapDepth(q.map, t) ? 1.0 : 0.0, zb > mapDepth(q.map, t + ivec2(1, 0)) ? 1.0 : 0.0,
                  zb > mapDepth(q.map, t + ivec2(0, 1)) ? 1.0 : 0.0,
                  zb > mapDepth(q.map, t + ivec2(1, 1)) ? 1.0 : 0.0);
    return mix(mix(g.x, g.y, f.x), mix(g.z, g.w, f.x), f.y);
}

float shadowIntensityPcss(ShadowQuery q) {
    float zb = q.zf - receiverBias(q, uConstantBias, uSlopeBias);
    vec2 c = q.uv * uMapTexels;
    float search = clamp(penumbraWidth(q, q.depthRange.x) / q.texelWorld, 1.0, uMaxKernelTexels);
    float blockerSum = 0.0, blockers = 0.0;
    const int N = 4;  // (2N + 1)² search taps
    for (int y = -N; y <= N; ++y)
        for (int x = -N; x <= N; ++x) {
            float z = mapDepth(q.map, ivec2(floor(c + vec2(x, y) * (0.5 * search / float(N)))));
            if (z < zb) { blockerSum += z; blockers += 1.0; }
        }
    if (blockers == 0.0) return 0.0;
    float w = penumbraWidth(q, worldDepth(q, blockerSum / blockers));
    float kernel = clamp(w / q.texelWorld, 1.0, uMaxKernelTexels);
    float sum = 0.0;
    for (int y = -N; y <= N; ++y)
        for (int x = -N; x <= N; ++x)
            sum += pcssBilinearTest(q, c + vec2(x, y) * (0.5 * kernel / float(N)), zb);
    return sum / float((2 * N + 1) * (2 * N + 1));
}
#define SL_SHADOW_INTENSITY shadowIntensityPcss
#endif
