// study_flicker: temporal stability, the main practical reason to filter a shadow map. The light
// turns about the vertical axis through its target by a small step per frame, over N frames;
// a technique's flicker is the mean frame-to-frame change of its G minus the truth's own change
// (mean |G_k+1 − G_k| over the pixels the light reaches in both frames, minus the same for the
// ray-traced truth): what the shadow changes beyond what the moving light really changes.
// Aliasing shimmers (a hard map's edge jumps a texel), a filter blurs the jump away, and a
// technique whose bias or leak depends on the sub-texel position adds its own.
// Why the light and not the camera: with the light still, the shadow map does not change as
// the camera moves (but cascades, which are fitted to the camera), so a camera path measures
// resampling of one fixed map; the light's motion re-rasterises the map every frame.
#pragma once

#include "renderer.h"
#include "scene.h"
#include "scene_truth.h"

#include <functional>
#include <vector>

namespace sl {

// Frame k of the sequence: every light turned by k·stepDegrees about the vertical axis through
// its target.
Scene movedLight(const Scene& scene, int frame, double stepDegrees);

// Mean |a − b| over the pixels reached (channel 0 ≥ 0.5) in both frames; 0 if none.
double meanChange(const Image& a, const Image& b, const Image& reachedA, const Image& reachedB);

// The truth of every frame (traced once per light size and cached on disk as any truth is) and
// its mean frame-to-frame change.
struct FlickerSequence {
    int frames = 0;
    double stepDegrees = 0;
    std::vector<SceneTruth> truths;
    double truthChange = 0;
};
FlickerSequence flickerSequence(const Scene& scene, int frames, double stepDegrees,
                                const ShaderLibrary& library, const SceneTruthOptions& options);

// A row's mean frame-to-frame change of G over the sequence (`rowScene`: the row's scene, moved
// here frame by frame; `plan`: how the study plans a row's frame).
double rowChange(Renderer& renderer, const Scene& rowScene, const FlickerSequence& sequence,
                 const std::function<PassPlan(const Scene&)>& plan);

}  // namespace sl
