// Renderer's programs: one compiled program per description (files and permutation, the plan's
// PassProgram), built on first use or all at once by compilePrograms, the warm-up before a
// render's first pass.
#include "render_internal.h"
#include "renderer.h"

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

GlProgram& Renderer::program(const PassProgram& description) {
    return program(description.vertexOrCompute, description.fragment, description.defines);
}

GlProgram& Renderer::passProgram(PassKind kind, int blurRadius,
                                 const std::vector<std::string>& defines) {
    return program(passProgramFor(kind, blurRadius, defines));
}

void Renderer::compilePrograms(const Scene& /*scene*/, const PassPlan& plan) {
    // The very programs the passes take: each pass's own description.
    for (const PlannedPass& pass : plan.passes) program(pass.program);
}

}  // namespace sl
