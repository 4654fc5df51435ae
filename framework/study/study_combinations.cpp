// study_combinations: see study_combinations.h.
#include "study_combinations.h"

#include "technique.h"

#include <algorithm>
#include <stdexcept>

namespace sl {
namespace {

FilterKind filterFromName(const std::string& name) {
    if (name == "none") return FilterKind::None;
    if (name == "gaussian") return FilterKind::Gaussian;
    if (name == "sat") return FilterKind::Sat;
    throw std::invalid_argument("filter \"" + name + "\": expected none, gaussian or sat");
}

}  // namespace

std::vector<Combination> combinations(const StudyOptions& o, std::vector<std::string>& notes) {
    std::vector<Combination> out;
    std::vector<double> lightSizes = o.lightSizes;
    if (lightSizes.empty()) lightSizes.push_back(-1.0);
    for (double lightSize : lightSizes)
    for (const std::string& spec : o.techniques) {
        auto [t, allParams] = parseTechniqueSpec(spec);
        const TechniqueRow& row = techniqueRow(t);
        // "momentBias" (α) is the scene's shadow.momentBias, not a row parameter: the study lets
        // a spec set it (msm4:momentBias=1e-4) so that α can be swept like the rest.
        std::vector<std::pair<std::string, double>> params;
        double momentBias = -1.0;
        bool perPixel = false;  // msm4:perPixel=1, like α a scene setting, not a row parameter
        for (const auto& [name, value] : allParams)
            if (name == "momentBias") momentBias = value;
            else if (name == "perPixel" && row.perPixelSat) perPixel = value != 0.0;
            else params.emplace_back(name, value);
        std::vector<FilterKind> filters;
        for (const auto& f : o.filters) {
            const FilterKind k = filterFromName(f);
            if (std::count(row.filters.begin(), row.filters.end(), k)) filters.push_back(k);
        }
        if (filters.empty()) {
            filters.push_back(row.filters.front());
            if (lightSize == lightSizes.front())
            notes.push_back(spec + ": none of the requested filters applies; its own (" +
                            std::string(toString(row.filters.front())) + ") is used");
        }
        for (int size : o.mapSizes)
            for (FilterKind f : filters) {
                if (f == FilterKind::None) {
                    out.push_back({spec, t, params, momentBias, f, 0, size, lightSize});
                    continue;
                }
                ShadowEffect fx;
                fx.technique = t;
                fx.filter = f;
                const bool boxPerPixel = perPixel && f == FilterKind::Sat;
                if ((!kernelReachesImage(fx) || boxPerPixel) && !o.radii.empty()) {  // one frame
                    out.push_back({spec, t, params, momentBias, f, o.radii.front(), size, lightSize,
                                   boxPerPixel});
                    if (size == o.mapSizes.front() && lightSize == lightSizes.front() &&
                        o.radii.size() > 1)
                        notes.push_back(spec + ": its " + toString(f) + " kernel does not reach the "
                                        "image (it picks its box per pixel): one row, radius " +
                                        std::to_string(o.radii.front()));
                    continue;
                }
                for (int r : o.radii)
                    out.push_back({spec, t, params, momentBias, f, r, size, lightSize});
            }
    }
    return out;
}

}  // namespace sl
