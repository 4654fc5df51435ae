// msm_sweep: the sweep's cases and its solver-free checks (see the header).
#include "msm_sweep.h"

#include "msm_robustness.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace sl {

MsmSweepCases generateMsmSweep(int vectors, uint64_t seed) {
    MsmSweepCases c;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    for (int v = 0; v < vectors; ++v) {
        const int parts = 1 + int(U(rng) * 4);
        glm::dvec4 b(0.0);
        double weightSum = 0.0, zmin = 1.0;
        std::vector<double> ws;
        for (int p = 0; p < parts; ++p) ws.push_back(U(rng) + 1e-3), weightSum += ws.back();
        for (double w : ws) {
            w /= weightSum;
            const double kind = U(rng);
            if (kind < 0.5) {  // a point mass; sometimes exactly at 0 or 1
                const double z = kind < 0.05 ? 0.0 : kind < 0.1 ? 1.0 : U(rng);
                b += w * glm::dvec4(z, z * z, z * z * z, z * z * z * z);
                zmin = std::min(zmin, z);
            } else {  // a uniform interval [a, a + len], len log-uniform in [1e-5, 1]
                const double len = std::pow(10.0, -5.0 * U(rng));
                const double a = U(rng) * (1.0 - len);
                for (int k = 1; k <= 4; ++k)
                    b[k - 1] += w * (std::pow(a + len, k + 1) - std::pow(a, k + 1)) / ((k + 1) * len);
                zmin = std::min(zmin, a);
            }
        }
        glm::vec4 bf(b);
        const bool perturb = U(rng) < 0.25;
        if (perturb) {  // adversarial: up to ±64 ulp per channel, or ±1e-6 absolute
            for (int k = 0; k < 4; ++k) {
                const int ulps = int((U(rng) - 0.5) * 128);
                if (U(rng) < 0.5)
                    for (int i = 0; i < std::abs(ulps); ++i) bf[k] = std::nextafter(bf[k], ulps > 0 ? 2.0f : -1.0f);
                else
                    bf[k] = std::max(0.0f, bf[k] + float((U(rng) - 0.5) * 2e-6));
            }
        }
        float zf[kMsmSweepDepthsPerVector] = {float(zmin) - kSweepFrontMargin - float(U(rng)) * 0.05f,
                                              float(U(rng) * 1.1 - 0.05), float(U(rng) * 1.1 - 0.05),
                                              float(U(rng) * 1.1 - 0.05)};
        std::sort(zf, zf + kMsmSweepDepthsPerVector);
        for (float z : zf) c.b.push_back(bf), c.zf.push_back(z);
        c.minDepth.push_back(float(zmin));
        c.perturbed.push_back(perturb);
    }
    return c;
}

CantelliBounds msmCantelliBounds(glm::vec4 b, float zf, float alpha) {
    // A bias of weight a toward a distribution on [-1, 1] moves the mean by at most 2a and
    // raises the variance by at most 5a (its own variance <= 1, plus a(1 - a)·(mean gap)² <= 4a).
    const double a = std::max(0.0f, alpha);
    const double mean = b.x, variance = std::max(0.0, double(b.y) - mean * mean) + 5 * a;
    CantelliBounds out;
    const double z = zf;
    if (z > mean + 2 * a) {
        const double t = z - mean - 2 * a;
        out.lower = t * t / (variance + t * t);
    } else if (z < mean - 2 * a) {
        const double t = mean - 2 * a - z;
        out.upper = variance / (variance + t * t);
    }
    return out;
}

MsmSweepReport checkMsmSweep(const MsmSweepCases& c, const std::vector<float>& g, float alpha) {
    MsmSweepReport r;
    r.cases = std::min(c.b.size(), g.size());
    r.vectors = r.cases / kMsmSweepDepthsPerVector;
    r.stub = r.cases > 0 && std::all_of(g.begin(), g.begin() + long(r.cases), [](float v) { return v == -1.0f; });
    if (r.stub) return r;
    const float frontMax = std::max(kSweepFrontMax, 3 * alpha);
    for (size_t i = 0; i < r.cases; ++i) {
        const size_t v = i / kMsmSweepDepthsPerVector;
        const float G = g[i];
        if (!(std::isfinite(G) && G >= 0.0f && G <= 1.0f))
            ++r.notInRange, r.problems.push_back({i, "not in [0,1]", 0});
        if (i % kMsmSweepDepthsPerVector && std::isfinite(G) && std::isfinite(g[i - 1])) {
            const double drop = double(g[i - 1]) - G;
            r.worstDrop = std::max(r.worstDrop, drop);
            if (drop > kMonotoneSlack) ++r.nonMonotone, r.problems.push_back({i, "non-monotone (bound: the G before)", g[i - 1]});
        }
        if (c.perturbed[v]) continue;
        if (c.zf[i] <= c.minDepth[v] - kSweepFrontMargin) {
            ++r.checkedFront;
            if (std::isfinite(G)) r.worstFront = std::max(r.worstFront, double(G));
            if (!(G <= frontMax)) ++r.frontLeak, r.problems.push_back({i, "in front of every occluder", frontMax});
        }
        ++r.checkedCantelli;
        const CantelliBounds cb = msmCantelliBounds(c.b[i], c.zf[i], alpha);
        if (!std::isfinite(G)) continue;
        const double below = cb.lower - G, above = G - cb.upper;
        r.worstCantelli = std::max({r.worstCantelli, below, above});
        if (below > kSweepCantelliSlack) ++r.belowCantelli, r.problems.push_back({i, "below the Cantelli bound", cb.lower});
        if (above > kSweepCantelliSlack) ++r.aboveCantelli, r.problems.push_back({i, "above the Cantelli bound", cb.upper});
    }
    return r;
}

std::string msmSweepSummary(const MsmSweepReport& r, const MsmSweepCases& c, const std::vector<float>& g,
                            float alpha, size_t listed) {
    std::string s;
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "sweep: %zu cases (%zu moment vectors x %d fragment depths; alpha %g)\n", r.cases,
                  r.vectors, kMsmSweepDepthsPerVector, double(alpha));
    s += buf;
    if (r.stub) return s + "  every G is the stub value -1: momentShadowIntensity is not implemented yet\n";
    s += "  checks that need no 4MSM solver (the exact value is not checked here):\n";
    auto line = [&](const char* what, size_t n, size_t of, const char* detail) {
        std::snprintf(buf, sizeof buf, "  %-50s %8zu failures of %zu  %s\n", what, n, of, detail);
        s += buf;
    };
    char d[128];
    line("G finite, in [0, 1]", r.notInRange, r.cases, "");
    std::snprintf(d, sizeof d, "(largest drop %.3g)", r.worstDrop);
    line("monotone in zf (G may drop <= 1e-3)", r.nonMonotone, r.cases - r.vectors, d);
    std::snprintf(d, sizeof d, "(largest G %.3g)", r.worstFront);
    std::snprintf(buf, sizeof buf, "G <= %g where zf is >= 0.01 in front of every occluder", double(std::max(kSweepFrontMax, 3 * alpha)));
    const std::string front = buf;
    line(front.c_str(), r.frontLeak, r.checkedFront, d);
    std::snprintf(d, sizeof d, "(furthest outside %.3g)", std::max(0.0, r.worstCantelli));
    line("within the mean/variance (Cantelli) bounds +- 1e-3", r.belowCantelli + r.aboveCantelli,
         r.checkedCantelli, d);
    s += "  (in front and Cantelli: the unperturbed vectors; perturbed ones may leave the moment space)\n";
    if (r.failures() == 0) return s + "  no failures\n";
    std::snprintf(buf, sizeof buf, "  %zu failures; the first %zu (probe msm --input of these rows "
                  "reproduces them; --out writes them all):\n", r.failures(), std::min(listed, r.problems.size()));
    s += buf;
    for (size_t k = 0; k < r.problems.size() && k < listed; ++k) {
        const auto& p = r.problems[k];
        const glm::vec4 b = c.b[p.index];
        std::snprintf(buf, sizeof buf, "    %s: b = (%.9g, %.9g, %.9g, %.9g), zf = %.9g, G = %.9g (bound %.9g)\n",
                      p.what.c_str(), b.x, b.y, b.z, b.w, c.zf[p.index], g[p.index], p.bound);
        s += buf;
    }
    return s;
}

}  // namespace sl
