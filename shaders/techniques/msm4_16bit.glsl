// techniques/msm4_16bit.glsl: 4MSM from 16-bit moments (Peters & Klein 2015, "optimized moment
// quantization"). Raw moments (z, z², z³, z⁴) are nearly collinear, so quantising each to 16
// bits destroys the differences the Cholesky solve needs. A fixed 4×4 transform Θ (and an offset
// on the first row) spreads them over [0, 1]⁴ before storage in RGBA16 (UNORM): half the memory
// of RGBA32F. A filter reads the map widened to RGBA32F (the stage contract's format), so the
// filtered moments keep float32 precision. Lighting undoes Θ (Θ⁻¹), biases the moments by
//   α = quantizedMomentBias (≈ 6·10⁻⁵: the quantisation error is larger than float32's) toward
//   (½, ⅓, ¼, ⅕), the moments of the uniform distribution on [0, 1]: unlike (½, ½, ½, ½) (two
//   points, a singular Hankel matrix) it is strictly positive definite, so any α > 0 moves a
//   quantised, slightly invalid vector back inside;
// then hands them to the solution's momentShadowIntensity (msm.glsl), which adds its own
// float32 bias uMomentBias toward (½, ½, ½, ½).

// q = Θ b + (0.035955884801, 0, 0, 0); columns of the mat4 are the rows of Peters' table.
vec4 msmQuantize16(vec4 b) {
    mat4 theta = mat4(-2.07224649, 13.7948857237, 0.105877704, 9.7924062118,
                      32.23703778, -59.4683975703, -1.9077466311, -33.7652110555,
                      -68.571074599, 82.0359750338, 9.3496555107, 47.9456096605,
                      39.3703274134, -35.364903257, -6.6543490743, -23.9728048165);
    return theta * b + vec4(0.035955884801, 0.0, 0.0, 0.0);
}

vec4 msmDequantize16(vec4 q) {
    mat4 inverse = mat4(0.2227744146, 0.1549679261, 0.1451988946, 0.163127443,
                        0.0771972861, 0.1394629426, 0.2120202157, 0.2591432266,
                        0.7926986636, 0.7963415838, 0.7258694464, 0.6539092497,
                        0.0319417555, -0.1722823173, -0.2758014811, -0.3376131734);
    return inverse * (q - vec4(0.035955884801, 0.0, 0.0, 0.0));
}

#ifndef SL_PROBE
uniform float uQuantizedMomentBias;
#endif

#ifdef SL_STAGE_MSM
float msm4QuantizedShadowIntensity(vec4 q, float zf, float alpha) {
    vec4 b = mix(msmDequantize16(q), vec4(0.5, 1.0 / 3.0, 0.25, 0.2), alpha);
    return momentShadowIntensity(b, zf);
}
#endif

#ifndef SL_PROBE
float shadowIntensityMsm4_16bit(ShadowQuery q) {
    return msm4QuantizedShadowIntensity(filteredMap(q.map, 0, q.uv), q.zf, uQuantizedMomentBias);
}
#define SL_SHADOW_INTENSITY shadowIntensityMsm4_16bit
#endif
