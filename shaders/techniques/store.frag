// techniques/store.frag: the shadow pass of every technique. It measures the fragment's distance
// from the light, takes the solution's relativeDepth (moments.glsl) and writes what the
// technique's row stores, per layer:
//   SL_STORE_DEPTH           z                         (hard, pcf, pcss, second-depth: R32F)
//   SL_STORE_VSM             (z, z²)                   (RG32F)
//   SL_STORE_EVSM2 / EVSM4   exp-warped moments        (evsm2.glsl / evsm4.glsl)
//   SL_STORE_CSM             (cos c_k z, sin c_k z)    (csm.glsl, SL_MAP_LAYERS RGBA32F)
//   SL_STORE_MOMENTS4        computeMoments(z)         (moments.glsl; RGBA32F)
//   SL_STORE_MOMENTS4_16BIT  Θ computeMoments(z) + offset  (msm4_16bit.glsl, RGBA16)
//   SL_STORE_FILE            techniqueStore(z) of the row's own file (one layer), which
//                            declares under SL_STORE_PASS what it stores
// A map that a filter stage reads is RGBA32F (VSM and EVSM2 then leave z and w blank).
// The CPU mirror of the store at z = 1 is the row's clear value (technique.h).
// (Helpers are included unconditionally: includes are once per program, whatever the #if.)
#include "moments.glsl"
#undef SL_STAGE_MSM  // the shadow pass reconstructs nothing: no msm.glsl here
#define SL_PROBE  // the technique files' functions only: no samplers, no uniforms
#include "techniques/common.glsl"
#include "techniques/evsm_common.glsl"
#include "techniques/csm.glsl"
#include "techniques/msm4_16bit.glsl"
#ifdef SL_STORE_FILE
#define SL_STORE_PASS  // the row's file: its techniqueStore(z) and the uniforms that reads
#include SL_TECHNIQUE_FILE
#endif
#undef SL_PROBE
uniform float uPositiveExponent;
uniform float uNegativeExponent;

in vec3 vWorldPosition;
in vec3 vWorldNormal;

uniform vec3 uLightEye;
uniform vec3 uLightForward;
uniform vec2 uDepthRange;

layout(location = 0) out vec4 outLayers[SL_MAP_LAYERS];

void main() {
    float z = relativeDepth(dot(vWorldPosition - uLightEye, uLightForward), uDepthRange);
#if defined(SL_STORE_DEPTH)
    outLayers[0] = vec4(z, 0.0, 0.0, 0.0);
#elif defined(SL_STORE_VSM)
    outLayers[0] = vec4(z, z * z, 0.0, 0.0);
#elif defined(SL_STORE_EVSM2) || defined(SL_STORE_EVSM4)
    float cp = min(uPositiveExponent, 42.0);
    float wp = evsmWarp(z, cp);
#if defined(SL_STORE_EVSM4)
    float cn = min(uNegativeExponent, 42.0);
    float wn = -exp(-cn * (2.0 * z - 1.0));
    outLayers[0] = vec4(wp, wp * wp, wn, wn * wn);
#else
    outLayers[0] = vec4(wp, wp * wp, 0.0, 0.0);
#endif
#elif defined(SL_STORE_CSM)
    for (int l = 0; l < SL_MAP_LAYERS; ++l) {
        float c1 = kPi * float(4 * l + 1), c2 = kPi * float(4 * l + 3);
        bool second = 2 * l + 2 <= SL_CSM_TERMS;
        outLayers[l] = vec4(cos(c1 * z), sin(c1 * z), second ? cos(c2 * z) : 0.0,
                            second ? sin(c2 * z) : 0.0);
    }
#elif defined(SL_STORE_MOMENTS4)
    outLayers[0] = computeMoments(z);
#elif defined(SL_STORE_MOMENTS4_16BIT)
    outLayers[0] = msmQuantize16(computeMoments(z));
#elif defined(SL_STORE_FILE)
    outLayers[0] = techniqueStore(z);
#endif
}
