// techniques/msm_soft.glsl: moment soft shadows (Peters et al. 2016): PCSS's three steps, each
// from the moments' SAT in a constant number of reads.
//   1. blocker search: the moments averaged over a box as wide as the penumbra a blocker at the
//      near plane would cast (≤ searchTexels); the canonical representation through z_f gives
//      the fraction of blockers and their mean depth z_b (msmBlockers)
//   2. penumbra: w = lightSize · (d_r − d_b) / d_b (as pcss.glsl), in texels w / texelWorld,
//      clamped to [1, maxKernelTexels]
//   3. G = Hamburger 4MSM of the moments averaged over that per-pixel box (α = momentBias)
// The SAT lets each pixel choose its own blur: penumbrae harden toward contact.
#include "techniques/msm_hamburger.glsl"

#ifndef SL_PROBE
uniform float uMomentBias;
uniform float uSearchTexels;
uniform float uMaxKernelTexels;

float shadowIntensityMsmSoft(ShadowQuery q) {
    vec2 c = q.uv * uMapTexels;
    float search = clamp(penumbraWidth(q, q.depthRange.x) / q.texelWorld, 2.0, uSearchTexels);
    vec2 blockers = msmBlockers(boxAverage(q.map, 0, c, vec2(search)), q.zf, uMomentBias);
    if (blockers.x <= 0.0) return 0.0;
    float w = penumbraWidth(q, worldDepth(q, blockers.y));
    float kernel = clamp(w / q.texelWorld, 1.0, uMaxKernelTexels);
    return msmHamburger(boxAverage(q.map, 0, c, vec2(kernel)), q.zf, uMomentBias, vec4(0.5));
}
#define SL_SHADOW_INTENSITY shadowIntensityMsmSoft
#endif
