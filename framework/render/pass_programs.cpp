// Renderer's programs: which files and permutation each pass kind compiles, built on first use
// or all at once by compilePrograms, the warm-up before a render's first pass.
#include "render_internal.h"
#include "renderer.h"

#include <set>
#include <stdexcept>
#include <utility>

namespace sl {

GlProgram& Renderer::program(const std::string& first, const std::string& fragment,
                             const std::vector<std::string>& defines) {
    std::string key = first + "|" + fragment;
    for (const auto& d : defines) key += "|" + d;
    auto& slot = programs_[key];
    if (!slot) {
        slot = std::make_unique<GlProgram>(
            fragment.empty() ? GlProgram::compute(library_, first, defines)
                             : GlProgram::graphics(library_, first, fragment, defines));
    }
    return *slot;
}

GlProgram& Renderer::passProgram(PassKind kind, int blurRadius,
                                 const std::vector<std::string>& defines) {
    switch (kind) {
        case PassKind::Shadow: return program("scene.vert", "techniques/store.frag", defines);
        case PassKind::ShadowSecond:
            return program("scene.vert", "techniques/second_depth_peel.frag", defines);
        case PassKind::Widen: return program("widen.comp", "", {});
        case PassKind::GaussianX:
        case PassKind::GaussianY:
            // The radius is a compile-time constant (one program per radius): llvmpipe then
            // unrolls the taps and keeps the window in registers (docs/performance.md).
            return program("gaussian_blur.comp", "",
                           {"SL_BLUR_RADIUS=" + std::to_string(blurRadius)});
        case PassKind::SatRows:
        case PassKind::SatColumns: return program("sat.comp", "", {});
        case PassKind::SatResolve: return program("sat_resolve.comp", "", {});
        case PassKind::Lighting: return program("scene.vert", "lighting.frag", defines);
    }
    throw std::logic_error("no program for this pass");
}

void Renderer::compilePrograms(const Scene& /*scene*/, const PassPlan& plan) {
    // The very programs the passes take: the Gaussians' with the scene's radius (a
    // compile-time constant), the lighting's for the plan.
    for (const PlannedPass& pass : plan.passes) {
        if (pass.kind == PassKind::Lighting) lightingProgram(plan);
        else passProgram(pass.kind, plan.effect.gaussianRadius, plan.defines);
    }
}

GlProgram& Renderer::lightingProgram(const PassPlan& plan) {
    // The slots (light, cascade) with maps, as the renderer allocates them.
    std::set<std::pair<int, int>> slots;
    for (int light : plan.shadowLights) slots.insert({light, 0});
    for (const PlannedCascade& c : plan.cascades) slots.insert({c.light, c.cascade});
    std::vector<std::string> defines = plan.defines;
    defines.push_back("SL_SHADOW_SLOTS=" + std::to_string(slots.size()));
    return passProgram(PassKind::Lighting, 0, defines);
}

}  // namespace sl
