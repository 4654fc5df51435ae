// techniques/second_depth.glsl: the bias-free variant of the course notes: compare against the
// midpoint of the first and second surfaces seen from the light (Woo 1992; Wang & Molnar's
// second-depth map is the limit where only the second counts).
//   G = 1 if z_f > (z1 + z2) / 2, else 0
//   z1     first (nearest) relative depth of the texel (the shadow pass)
//   z2     second depth (the peeling pass, second_depth_peel.frag); 1 where nothing lies behind
// No bias: a lit surface is z1 itself, half a gap in front of the threshold. It fails where
// z2 − z1 is tiny (thin objects) or where the first surface is also the receiver's back face.
float secondDepthShadowTest(float z1, float z2, float zf) {
    return zf > 0.5 * (z1 + z2) ? 1.0 : 0.0;
}

#ifndef SL_PROBE
float shadowIntensitySecondDepth(ShadowQuery q) {
    ivec2 t = ivec2(floor(q.uv * uMapTexels));
    return secondDepthShadowTest(mapDepth(q.map, t), mapDepth(q.map + 1, t), q.zf);
}
#define SL_SHADOW_INTENSITY shadowIntensitySecondDepth
#endif
