// techniques/msm_soft.glsl: moment soft shadows (Peters et al. 2016): PCSS's three steps, each
// from the moments' SAT in a constant number of reads.
//   1. blocker search: the moments averaged over a box as wide as the penumbra a blocker at the
//      near plane would cast (≤ searchTexels); the canonical representation through z_f gives
//      the fraction of blockers and their mean depth z_b (msmBlockers)
//   2. penumbra: w = lightSize · (d_r − d_b) / d_b (as pcss.glsl), in texels w / texelWorld,
//      clamped to [1, maxKernelTexels]
//   3. G = the solution's momentShadowIntensity (msm.glsl) of the moments averaged over that
//      per-pixel box (the solution's satBoxAverage)
// The SAT lets each pixel choose its own blur: penumbrae harden toward contact. The blocker
// search needs the canonical representation's roots (techniques/msm_hamburger.glsl), which
// solve the msm stage: instructor kit only.
#include "techniques/msm_hamburger.glsl"  // instructor kit only (it solves the msm stage)
#ifndef SL_PROBE
uniform float uSearchTexels;
uniform float uMaxKernelTexels;

float shadowIntensityMsmSoft(ShadowQuery q) {
    vec2 c = q.uv * uMapTexels;
    float search = clamp(penumbraWidth(q, q.depthRange.x) / q.texelWorld, 2.0, uSearchTexels);
    vec2 blockers = msmBlockers(satBoxAverage(uShadowMaps[q.map], c, vec2(search)), q.zf,
                                uMomentBias);
    if (blockers.x <= 0.0) return 0.0;
    float w = penumbraWidth(q, worldDepth(q, blockers.y));
    float kernel = clamp(w / q.texelWorld, 1.0, uMaxKernelTexels);
    return momentShadowIntensity(satBoxAverage(uShadowMaps[q.map], c, vec2(kernel)), q.zf);
}
#define SL_SHADOW_INTENSITY shadowIntensityMsmSoft
#endif
