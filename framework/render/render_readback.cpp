// Renderer's read-back: the maps of every shadowing light into RenderResult's images, and the
// stub detection that tells a student's unimplemented stage (output -1) from a wrong one.
#include "render_internal.h"

#include <algorithm>

namespace sl::render_detail {
bool stubOutput(const Image& out, const Image* in, bool everywhere) {
    for (std::size_t i = 0, n = std::size_t(out.width) * out.height; i < n; ++i) {
        const bool stub = out.stubTexel(i);
        if (everywhere && !stub) return false;
        if (!everywhere && stub && !(in && in->stubTexel(i))) return true;
    }
    return everywhere;
}

void noteStub(const ShaderLibrary& library, RenderResult& result, const std::string& file,
              const std::string& function) {
    std::string line = library.displayPath(library.resolve(file)) + ": " + function +
                       ": not implemented yet (its output is the stub value -1)";
    for (const auto& existing : result.stubNotes)
        if (existing == line) return;
    result.stubNotes.push_back(line);
}

void readBack(const ShaderLibrary& library, const TechniqueRow& row, const ShadowEffect& fx,
              const PassPlan& plan, ShadowMapSet& maps, RenderResult& result) {
    for (auto& [id, m] : maps) {
        const int li = id.light;
        const std::string suffix =
            (li == plan.shadowLights.front() ? "" : "_light" + std::to_string(li)) +
            (id.cascade > 0 ? "_cascade" + std::to_string(id.cascade) : "");
        const auto& rawLayers = m.tex.at("raw");
        Image raw = rawLayers.front().read();
        if (!row.studentStages) {
            for (size_t k = 1; k < rawLayers.size(); ++k)
                result.images["moments_raw" + suffix + "_layer" + std::to_string(k)] =
                    rawLayers[k].read();
            if (m.tex.count("second")) result.images["second_depth" + suffix] = m.one("second").read();
            if (m.tex.count("filtered")) {
                const auto& filteredLayers = m.tex.at("filtered");
                result.images["moments_filtered" + suffix] = filteredLayers.front().read();
                for (size_t k = 1; k < filteredLayers.size(); ++k)
                    result.images["moments_filtered" + suffix + "_layer" + std::to_string(k)] =
                        filteredLayers[k].read();
            }
            else if (!m.tex.count("sat-hi"))
                result.images["moments_filtered" + suffix] = raw;
            result.images["moments_raw" + suffix] = std::move(raw);
            continue;
        }
        if (stubOutput(raw, nullptr)) noteStub(library, result, "moments.glsl", "computeMoments");
        if (fx.filter == FilterKind::Gaussian) {
            Image filtered = m.one("filtered").read();
            if (stubOutput(filtered, &raw))
                noteStub(library, result, "gaussian_blur.comp", "gaussian blur pass");
            result.images["moments_filtered" + suffix] = std::move(filtered);
        } else if (fx.filter == FilterKind::Sat) {
            Image sat = m.one("sat").read();
            if (stubOutput(sat, &raw)) noteStub(library, result, "sat.comp", "prefix-sum pass");
            if (plan.passes.end() != std::find_if(plan.passes.begin(), plan.passes.end(),
                                                  [](const PlannedPass& p) {
                                                      return p.kind == PassKind::SatResolve;
                                                  })) {
                Image filtered = m.one("filtered").read();
                // A stub table makes a correct lookup return ~0, never -1 everywhere.
                if (stubOutput(filtered, &sat) || stubOutput(filtered, nullptr, true))
                    noteStub(library, result, "sat_lookup.glsl", "satBoxAverage");
                result.images["moments_filtered" + suffix] = std::move(filtered);
            }
            result.images["sat" + suffix] = std::move(sat);
        } else {
            result.images["moments_filtered" + suffix] = raw;
        }
        result.images["moments_raw" + suffix] = std::move(raw);
    }
}

}  // namespace sl::render_detail
