// PassPlan: the passes a scene's declared effects need, in execution order — and no others.
// A scene with no shadowing light has no shadow pass; a filter of `none` dispatches nothing;
// a light's shadow map is rendered once however many cameras see it.
#pragma once

#include "scene.h"

#include <string>
#include <vector>

namespace sl {

enum class PassKind {
    Shadow,      // light view: moments.glsl writes the moments into the shadow map
    GaussianX,   // gaussian_blur.comp along rows
    GaussianY,   // gaussian_blur.comp along columns
    SatRows,     // sat.comp prefix sums along rows
    SatColumns,  // sat.comp prefix sums along columns
    SatResolve,  // sat_lookup.glsl at every texel: the filtered moments, for output only
    Lighting,    // camera view: msm.glsl (and sat_lookup.glsl) shade the image
};

const char* toString(PassKind);

struct PlannedPass {
    PassKind kind;
    int light = -1;   // index into Scene::lights (shadow and filter passes)
    int camera = -1;  // index into Scene::cameras (lighting passes)
    std::string why;  // which declared effect calls for it
};

struct PlanOptions {
    // Produce the filtered moment map of a SAT scene (the SAT itself is not a moment map).
    // The grader and `render` want it; an interactive viewer does not.
    bool resolveSat = true;
};

struct PassPlan {
    std::vector<PlannedPass> passes;
    std::vector<int> shadowLights;  // lights that get a shadow map, in order
    int momentChannels = 0;         // channels the shadow map stores (MSM: 4; none: 0)
};

PassPlan planPasses(const Scene& scene, const PlanOptions& options = {});

// The plan as text, one numbered line per pass; with `millis` (one per pass) the time of each.
std::string explainPlan(const Scene& scene, const PassPlan& plan,
                        const std::vector<double>* millis = nullptr);

}  // namespace sl
