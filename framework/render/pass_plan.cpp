// planPasses: derive the pass list from the scene (see pass_plan.h).
#include "pass_plan.h"

#include <cstdio>

namespace sl {

const char* toString(PassKind kind) {
    switch (kind) {
        case PassKind::Shadow: return "shadow";
        case PassKind::GaussianX: return "gaussian-x";
        case PassKind::GaussianY: return "gaussian-y";
        case PassKind::SatRows: return "sat-rows";
        case PassKind::SatColumns: return "sat-columns";
        case PassKind::SatResolve: return "sat-resolve";
        case PassKind::Lighting: return "lighting";
    }
    return "?";
}

static int channelsFor(Technique technique) {
    switch (technique) {
        case Technique::Msm4: return 4;  // b = (z, z², z³, z⁴)
    }
    return 4;
}

PassPlan planPasses(const Scene& scene, const PlanOptions& options) {
    PassPlan plan;
    const ShadowEffect& fx = scene.shadow;
    for (int i = 0; i < int(scene.lights.size()); ++i) {
        if (!scene.lights[i].castsShadows) continue;
        plan.shadowLights.push_back(i);
        const std::string light = "light " + std::to_string(i);
        plan.passes.push_back({PassKind::Shadow, i, -1, light + " casts shadows"});
        switch (fx.filter) {
            case FilterKind::None: break;
            case FilterKind::Gaussian: {
                const std::string why = "gaussian filter, radius " +
                                        std::to_string(fx.gaussianRadius);
                plan.passes.push_back({PassKind::GaussianX, i, -1, why});
                plan.passes.push_back({PassKind::GaussianY, i, -1, why});
                break;
            }
            case FilterKind::Sat: {
                char why[64];
                std::snprintf(why, sizeof why, "sat filter, kernel %.2f texels",
                              fx.satKernelTexels);
                plan.passes.push_back({PassKind::SatRows, i, -1, why});
                plan.passes.push_back({PassKind::SatColumns, i, -1, why});
                if (options.resolveSat)
                    plan.passes.push_back(
                        {PassKind::SatResolve, i, -1, "filtered moments requested as output"});
                break;
            }
        }
    }
    if (!plan.shadowLights.empty()) plan.momentChannels = channelsFor(fx.technique);
    for (int c = 0; c < int(scene.cameras.size()); ++c)
        plan.passes.push_back({PassKind::Lighting, -1, c, "camera '" + scene.cameras[c].name + "'"});
    return plan;
}

std::string explainPlan(const Scene& scene, const PassPlan& plan,
                        const std::vector<double>* millis) {
    std::string out = "plan for " + scene.name + " (" + std::to_string(plan.passes.size()) +
                      " passes, technique " + toString(scene.shadow.technique) + ", filter " +
                      toString(scene.shadow.filter) + ", moments " +
                      std::to_string(plan.momentChannels) + " channels):\n";
    double total = 0.0;
    for (size_t i = 0; i < plan.passes.size(); ++i) {
        const PlannedPass& p = plan.passes[i];
        char line[256];
        std::snprintf(line, sizeof line, "  %2zu. %-12s %-30s", i + 1, toString(p.kind),
                      p.why.c_str());
        out += line;
        if (millis && i < millis->size()) {
            std::snprintf(line, sizeof line, " %9.2f ms", (*millis)[i]);
            out += line;
            total += (*millis)[i];
        }
        out += "\n";
    }
    if (millis) {
        char line[64];
        std::snprintf(line, sizeof line, "  total %44.2f ms\n", total);
        out += line;
    }
    return out;
}

}  // namespace sl
