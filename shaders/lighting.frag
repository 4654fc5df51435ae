// lighting.frag: shades the camera's view. Each light adds (1 - G)·(diffuse + specular) to
// the ambient term, where G is the shadow intensity of the technique compiled in: its row's
// file (SL_TECHNIQUE_FILE, a row of framework/scene/technique_table.cpp) defines
// shadowIntensity<X>(ShadowQuery). Every technique is a permutation of this one file,
// and every one runs on the solution's stage files: relativeDepth (moments.glsl), the SAT's
// satBoxAverage (sat_lookup.glsl, SL_FILTER_SAT) and, where it reconstructs with Hamburger 4MSM,
// momentShadowIntensity (msm.glsl, SL_STAGE_MSM).
// zf, the fragment's relative depth toward a light, is relativeDepth's, but for the grader's msm
// stage (SL_RELATIVE_DEPTH_GIVEN): there it is the reference's, read from an image, so that the
// stage compiles only the submission's msm.glsl. SL_RELATIVE_DEPTH_SHOWN writes that image: the
// first shadowing light's zf in G's place.
#ifdef SL_RELATIVE_DEPTH_GIVEN
uniform sampler2D uGivenRelativeDepth;  // R32F, the camera's size: zf of the first shadowing light
uniform int uFirstShadowLight;
#else
#include "moments.glsl"  // relativeDepth
#endif
#ifdef SL_FILTER_SAT
#include "sat_lookup.glsl"
#endif
#ifdef SL_STAGE_MSM
uniform float uMomentBias;  // α, handed to msm.glsl
#include "msm.glsl"
#endif
#include "techniques/common.glsl"
// The exponential warp that evsm2 and evsm4 share.
#include "techniques/evsm_common.glsl"
// The row's GLSL file (framework/scene/technique_table.cpp): it defines SL_SHADOW_INTENSITY.
#include SL_TECHNIQUE_FILE

// SL_MAX_LIGHTS, SL_MAX_CASCADES (per light) come as defines (framework/scene/scene_limits.h); a
// light's maps are "slots" SL_MAX_CASCADES·i + c.
// How many slots have maps (the renderer's lightingProgram sets it from the plan). With one,
// that slot's maps start at unit 0, a constant: llvmpipe then reads one known sampler instead
// of switching over the sampler array at every texelFetch (about a third of the SAT lookup's
// lighting pass). Unset: any number, the index a uniform.
#ifndef SL_SHADOW_SLOTS
#define SL_SHADOW_SLOTS (SL_MAX_LIGHTS * SL_MAX_CASCADES)
#endif

in vec3 vWorldPosition;
in vec3 vWorldNormal;

uniform vec3 uCameraPosition;
uniform vec3 uAmbient;
uniform vec3 uAlbedo;
uniform float uSpecular;
uniform float uShininess;

uniform int uLightCount;
uniform vec3 uLightEye[SL_MAX_LIGHTS];       // spot: position; directional: frustum eye
uniform vec3 uLightForward[SL_MAX_LIGHTS];
uniform vec3 uLightColor[SL_MAX_LIGHTS];     // colour × intensity
uniform int uLightIsSpot[SL_MAX_LIGHTS];
uniform float uLightCosHalfCone[SL_MAX_LIGHTS];
uniform int uLightShadowMap[SL_MAX_LIGHTS];  // >= 0: casts a shadow; -1: casts none
uniform vec2 uLightDepthRange[SL_MAX_LIGHTS];
// Per slot (light i, cascade c at SL_MAX_CASCADES·i + c; c = 0 without cascades): the map's
// light view and its first index into uShadowMaps.
uniform mat4 uSlotViewProjection[SL_MAX_LIGHTS * SL_MAX_CASCADES];
uniform int uSlotShadowMap[SL_MAX_LIGHTS * SL_MAX_CASCADES];
// Cascades (directional lights, cascades.h): how many (1: one map), the camera view depth at
// which each ends, and the camera they were fitted to.
uniform int uLightCascades[SL_MAX_LIGHTS];
uniform vec4 uLightCascadeFar[SL_MAX_LIGHTS];
uniform vec3 uCascadeCameraPosition;
uniform vec3 uCascadeCameraForward;
uniform float uDepthBias;   // subtracted from the fragment's relative depth (acne)
uniform float uLightSize[SL_MAX_LIGHTS];          // emitter diameter (PCSS, msm-soft)
uniform float uSlotFrustumScale[SL_MAX_LIGHTS * SL_MAX_CASCADES];  // frustum width: spot × depth
uniform float uNormalOffset = 0.0;                // texels along the normal (hard, pcf, pcss)

layout(location = 0) out vec4 outColor;
layout(location = 1) out float outShadow;  // G of the first shadowing light

// The slot of light i's map that shades p: its only map, or the cascade whose slice of the
// camera's view depth holds p, or a later one if p lies outside that cascade's window (a
// tight fit leaves the slice's edges to its neighbour). -1: no cascade covers p.
int shadowSlot(int i, vec3 p) {
    int first = SL_MAX_CASCADES * i;
    if (uLightCascades[i] <= 1) return first;
    float depth = dot(p - uCascadeCameraPosition, uCascadeCameraForward);
    int c = 0;
    while (c < uLightCascades[i] - 1 && depth > uLightCascadeFar[i][c]) ++c;
    do {  // c < uLightCascades[i] here: test at the end (no masked extra pass, see main)
        vec4 clip = uSlotViewProjection[first + c] * vec4(p, 1.0);
        if (all(lessThanEqual(abs(clip.xy / clip.w), vec2(1.0)))) return first + c;
        ++c;
    } while (c < uLightCascades[i]);
    return -1;
}

// G for light i at world position p from the technique's row and the maps in `slot`, from
// unit `map` on; 0 outside its frustum.
float shadowIntensityAt(int i, int slot, int map, vec3 p) {
    vec3 n = normalize(vWorldNormal);
    vec3 l = uLightIsSpot[i] != 0 ? normalize(uLightEye[i] - p) : -uLightForward[i];
    float cosTheta = clamp(abs(dot(n, l)), 1e-4, 1.0);
    float d0 = dot(p - uLightEye[i], uLightForward[i]);
    float frustum = uLightIsSpot[i] != 0 ? uSlotFrustumScale[slot] * d0 : uSlotFrustumScale[slot];
    // Normal offset: move the receiver along its normal (toward the light's side) by texels.
    p += (dot(n, l) < 0.0 ? -n : n) * (uNormalOffset * frustum / uMapTexels.x);
    vec4 clip = uSlotViewProjection[slot] * vec4(p, 1.0);
    vec3 ndc = clip.xyz / clip.w;
    if (clip.w <= 0.0 || any(greaterThan(abs(ndc.xy), vec2(1.0)))) return 0.0;
    ShadowQuery q;
    q.map = map;
    q.uv = ndc.xy * 0.5 + 0.5;
    q.receiverDepth = dot(p - uLightEye[i], uLightForward[i]);
    q.depthRange = uLightDepthRange[i];
#ifdef SL_RELATIVE_DEPTH_GIVEN
    // Only the first shadowing light's G is graded; the others shade as lit.
    if (i != uFirstShadowLight) return 0.0;
    float z = texelFetch(uGivenRelativeDepth, ivec2(gl_FragCoord.xy), 0).r;
#else
    float z = relativeDepth(q.receiverDepth, q.depthRange);
#endif
#ifdef SL_RELATIVE_DEPTH_SHOWN
    return z;
#endif
    q.zf = z - uDepthBias;
    q.tanTheta = min(sqrt(1.0 - cosTheta * cosTheta) / cosTheta, 10.0);
    q.isSpot = uLightIsSpot[i];
    q.frustumScale = uSlotFrustumScale[slot];
    q.lightSize = uLightSize[i];
    q.texelWorld = texelWorldAt(q, q.receiverDepth);
    q.texelDepth = q.texelWorld / (q.depthRange.y - q.depthRange.x);
    float G = SL_SHADOW_INTENSITY(q);
    // relativeDepth still the stub (-1): G is "not computed", never "lit". -3 keeps a stub G
    // (-1) visible too, so that the renderer names both stages (noteLightingStubs).
    if (z == -1.0) G = G == -1.0 ? -3.0 : -2.0;
    return G;
}

// G for light i at world position p, from the map (cascade) that covers p. Sampler arrays take
// dynamically uniform indices only (llvmpipe shades a SIMD group with one index): so the loop
// runs over the light's slots, a uniform count, and shades with the one chosen, so that every
// map index is the loop's, never a per-pixel value. With a single slot there is nothing to
// choose, and its maps start at the constant unit 0.
float shadowIntensity(int i, vec3 p) {
#if SL_SHADOW_SLOTS == 0
    return 0.0;  // no light has a map; llvmpipe would still run a lookup here, masked off
#elif SL_SHADOW_SLOTS == 1
    return shadowIntensityAt(i, SL_MAX_CASCADES * i, 0, p);
#else
    int slot = shadowSlot(i, p);
    float G = 0.0;
    int s = SL_MAX_CASCADES * i;
    int end = s + max(uLightCascades[i], 1);
    // do-while, not for: llvmpipe runs a for loop's body once more, all lanes masked off, after
    // the last iteration (a whole shadow lookup for nothing); a light has at least one slot.
    do {
        if (s == slot) G = shadowIntensityAt(i, s, uSlotShadowMap[s], p);
        ++s;
    } while (s < end);
    return G;
#endif
}

void main() {
    vec3 n = normalize(vWorldNormal);
    vec3 v = normalize(uCameraPosition - vWorldPosition);
    if (dot(n, v) < 0.0) n = -n;  // planes are seen from both sides
    vec3 color = uAmbient * uAlbedo;
    float firstShadow = 0.0;
    bool firstSeen = false;
    bool broken = false;
    // do-while, not for: llvmpipe runs a for loop's body once more, all lanes masked off, after
    // the last light, and that body holds the whole shadow lookup (it doubled the pass).
    int i = 0;
    if (uLightCount > 0) do {
        vec3 l = uLightIsSpot[i] != 0 ? normalize(uLightEye[i] - vWorldPosition)
                                      : -uLightForward[i];
        float cone = 1.0;
        if (uLightIsSpot[i] != 0) {
            float c = dot(-l, uLightForward[i]);
            cone = smoothstep(uLightCosHalfCone[i], mix(uLightCosHalfCone[i], 1.0, 0.1), c);
        }
        float G = 0.0;
        if (uLightShadowMap[i] >= 0) {
            G = shadowIntensity(i, vWorldPosition);
            if (!firstSeen) { firstShadow = G; firstSeen = true; }
            // Out of [0, 1] or NaN (a stub returns -1): shade as lit and hatch it in magenta
            // below, so the scene stays readable but the gap cannot be mistaken for light.
            if (!(G >= 0.0 && G <= 1.0)) { broken = true; G = 0.0; }
        }
        vec3 h = normalize(l + v);
        float diffuse = max(dot(n, l), 0.0);
        float specular = diffuse > 0.0 ? uSpecular * pow(max(dot(n, h), 0.0), uShininess) : 0.0;
        color += (1.0 - G) * cone * uLightColor[i] * (diffuse * uAlbedo + specular);
        ++i;
    } while (i < uLightCount);
    // Diagonal magenta stripes, 3 of every 8 pixels, where some light's G was not computed.
    bool stripe = ((int(gl_FragCoord.x) + int(gl_FragCoord.y)) & 7) < 3;
    outColor = broken && stripe ? vec4(1.0, 0.0, 1.0, 1.0) : vec4(color, 1.0);
    outShadow = firstShadow;
}
