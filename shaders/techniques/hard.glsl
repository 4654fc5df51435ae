// techniques/hard.glsl: hard shadows, one depth comparison (Williams 1978).
//   G = 1 if z_f − bias > z_map, else 0
//   z_map  the stored relative depth of the receiver's texel (nearest, no filtering)
//   z_f    the receiver's relative depth
//   bias   constantBias + slopeBias · texelDepth · tan θ: the constant covers the depth
//          quantisation of the map; the slope term covers the depth change across one texel of
//          a surface seen at angle θ from the light (acne at grazing light). The third bias,
//          normalOffset, moved the receiver along its normal before projection (lighting.frag).
#ifndef SL_PROBE
uniform float uConstantBias;
uniform float uSlopeBias;
#endif

float hardShadowTest(float zMap, float zf, float bias) {
    return zf - bias > zMap ? 1.0 : 0.0;
}

#ifndef SL_PROBE
float shadowIntensityHard(ShadowQuery q) {
    ivec2 t = ivec2(floor(q.uv * uMapTexels));
    return hardShadowTest(mapDepth(q.map, t), q.zf, receiverBias(q, uConstantBias, uSlopeBias));
}
#define SL_SHADOW_INTENSITY shadowIntensityHard
#endif
