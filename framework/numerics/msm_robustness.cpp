// msm_robustness: the catalogue cases plus, per case, a ladder of fragment depths for the
// monotonicity check, all in one probe dispatch (see the header).
#include "msm_robustness.h"

#include "probe.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sl {
namespace {

// Fragment depths at which every case's moments are also evaluated (sorted, with the
// case's own zf merged in): the whole range plus a margin outside [0, 1].
std::vector<float> zfLadder() {
    std::vector<float> z;
    for (int i = 0; i <= 48; ++i) z.push_back(-0.1f + 1.2f * float(i) / 48.0f);
    return z;
}

}  // namespace

std::vector<float> msmMonotoneLadder(const MsmCase& c) {
    std::vector<float> z = zfLadder();
    z.push_back(c.zf);
    std::sort(z.begin(), z.end());
    return z;
}

std::string RobustnessCase::problems() const {
    std::string p;
    auto add = [&](bool flag, const char* what) {
        if (flag) p += (p.empty() ? "" : ", ") + std::string(what);
    };
    add(nan, "NaN");
    add(inf, "Inf");
    add(outOfRange, "outside [0, 1]");
    add(nonMonotone, "non-monotone in zf");
    add(offExpected, "off from the exact value");
    return p;
}

std::string RobustnessReport::summary(int maxListed) const {
    char line[512];
    std::snprintf(line, sizeof line, "robustness: %zu hard cases, %d failed, score %.3f\n",
                  cases.size(), failed, score);
    std::string out = line;
    int listed = 0;
    for (const auto& c : cases) {
        if (c.ok()) continue;
        if (listed++ == maxListed) {
            out += "  ...\n";
            break;
        }
        std::snprintf(line, sizeof line,
                      "  %s: %s; b = (%.9g, %.9g, %.9g, %.9g), zf = %.9g -> G = %.9g "
                      "(expected %.6g ± %.3g)\n",
                      c.input.name.c_str(), c.problems().c_str(), c.input.b.x, c.input.b.y,
                      c.input.b.z, c.input.b.w, c.input.zf, c.G, c.input.expected, c.input.bound);
        out += line;
        if (c.nonMonotone) {
            std::snprintf(line, sizeof line,
                          "    G drops from %.9g at zf = %.9g to %.9g at zf = %.9g (the zf ladder: "
                          "shadowlab probe msm --generate zf-ladder)\n",
                          c.dropG0, c.dropZf0, c.dropG1, c.dropZf1);
            out += line;
        }
    }
    return out;
}

RobustnessReport probeMsmRobustness(const ShaderLibrary& library, float alpha) {
    const std::vector<MsmCase> catalogue = msmHardCaseCatalogue(alpha);
    const size_t L = zfLadder().size() + 1;  // the ladder plus the case's own zf
    std::vector<glm::vec4> b;
    std::vector<float> zf;
    for (const auto& c : catalogue)
        for (float v : msmMonotoneLadder(c)) b.push_back(c.b), zf.push_back(v);
    const std::vector<float> G = probeMomentShadowIntensity(library, b, zf, alpha);

    RobustnessReport report;
    for (size_t i = 0; i < catalogue.size(); ++i) {
        RobustnessCase r;
        r.input = catalogue[i];
        const float* g = &G[i * L];
        const float* z = &zf[i * L];
        for (size_t k = 0; k < L; ++k) {
            if (z[k] == r.input.zf) r.G = g[k];
            if (k > 0 && g[k] < g[k - 1] - kMonotoneSlack &&
                (!r.nonMonotone || g[k - 1] - g[k] > r.dropG0 - r.dropG1)) {
                r.nonMonotone = true;
                r.dropZf0 = z[k - 1], r.dropZf1 = z[k], r.dropG0 = g[k - 1], r.dropG1 = g[k];
            }
        }
        r.nan = std::isnan(r.G);
        r.inf = std::isinf(r.G);
        r.outOfRange = !r.nan && (r.G < 0.0f || r.G > 1.0f);
        r.offExpected = std::isfinite(r.input.expected) && std::isfinite(r.G) &&
                        std::abs(double(r.G) - r.input.expected) > r.input.bound;
        report.failed += r.ok() ? 0 : 1;
        report.cases.push_back(std::move(r));
    }
    report.score = report.cases.empty() ? 1.0
                                        : double(report.cases.size() - size_t(report.failed)) /
                                              double(report.cases.size());
    return report;
}

}  // namespace sl
