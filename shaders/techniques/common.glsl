// techniques/common.glsl: what the technique files share: the query a lighting function
// answers, the shadow-map array, filtered reads (bilinear, or a box from the solution's SAT
// through its satBoxAverage), the receiver's bias, and the geometry of a penumbra. Relative
// depth is the solution's relativeDepth (moments.glsl). Included by lighting.frag and the
// probe shader. SL_MAX_MAPS comes as a define (framework/scene/scene_limits.h).

// What the lighting pass knows about a receiver, in the light's shadow map.
struct ShadowQuery {
    int map;           // first index into uShadowMaps of this light's maps
    vec2 uv;           // position in the map, [0, 1]²
    float zf;          // receiver's relative depth (scene depth bias already subtracted)
    float tanTheta;    // tan of the angle between surface normal and light direction (≤ 10)
    float texelDepth;  // one texel's world width, in relative-depth units (slope bias)
    float texelWorld;  // one texel's world width at the receiver
    float receiverDepth;   // world depth along the light's axis
    vec2 depthRange;   // (near, far) of relative depth, world units
    float lightSize;   // emitter diameter, world units (directional: radians)
    int isSpot;
    float frustumScale;    // frustum width: spot × depth; directional as is
};

#ifndef SL_PROBE
#ifndef SL_MAX_MAPS
#error "SL_MAX_MAPS is not defined: the framework passes it with the technique's defines"
#endif
uniform sampler2D uShadowMaps[SL_MAX_MAPS];
#endif
uniform vec2 uMapTexels;  // map width and height, texels

// Linear world depth of a relative depth.
float worldDepth(ShadowQuery q, float z) {
    return q.depthRange.x + z * (q.depthRange.y - q.depthRange.x);
}

// World width of one map texel at world depth d.
float texelWorldAt(ShadowQuery q, float d) {
    return (q.isSpot != 0 ? q.frustumScale * d : q.frustumScale) / uMapTexels.x;
}

// Penumbra width (world units, at the receiver) for a blocker at world depth dB: similar
// triangles between the emitter and the blocker (PCSS, Fernando 2005).
float penumbraWidth(ShadowQuery q, float dB) {
    float dR = q.receiverDepth;
    return q.isSpot != 0 ? q.lightSize * (dR - dB) / max(dB, 1e-4) : q.lightSize * (dR - dB);
}

#ifndef SL_PROBE
// The depth of texel t (clamped to the map), nearest.
float mapDepth(int map, ivec2 t) {
    return texelFetch(uShadowMaps[map], clamp(t, ivec2(0), ivec2(uMapTexels) - 1), 0).r;
}

#ifdef SL_FILTER_SAT
uniform float uSatKernel;  // the scene's box width, texels
#endif

// The filtered map at the receiver: the box of the scene's width from the layer's summed-area
// table (the solution's sat.comp and satBoxAverage), or a bilinear read of the
// (Gaussian-filtered or raw) map.
vec4 filteredMap(int map, int layer, vec2 uv) {
#ifdef SL_FILTER_SAT
    return satBoxAverage(uShadowMaps[map + layer], uv * uMapTexels, vec2(uSatKernel));
#else
    return texture(uShadowMaps[map + layer], uv);
#endif
}
#endif

// Receiver bias of the depth-comparing techniques: constant + slope-scaled. The slope term is
// the depth change across `slopeBias` texels of a surface at angle θ to the light:
// slopeBias · texelWorld · tan θ, in relative-depth units.
float receiverBias(ShadowQuery q, float constantBias, float slopeBias) {
    return constantBias + slopeBias * q.texelDepth * q.tanTheta;
}

// Chebyshev–Cantelli: an upper bound of P(z >= t) from mean μ and variance σ².
float chebyshevUpperBound(vec2 m, float t, float minVariance) {
    float variance = max(m.y - m.x * m.x, minVariance);
    float d = t - m.x;
    return t <= m.x ? 1.0 : variance / (variance + d * d);
}

// Light-bleeding reduction: lit fractions below `amount` become 0, the rest rescale to [0, 1].
float reduceLightBleeding(float pMax, float amount) {
    return clamp((pMax - amount) / (1.0 - amount), 0.0, 1.0);
}
