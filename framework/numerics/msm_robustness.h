// msm_robustness: the grader's robustness stage. It probes a solution's momentShadowIntensity
// (msm.glsl) on the hard-case catalogue (probe_cases.h) and says, per case, what went wrong:
// NaN, Inf, a value outside [0, 1], G decreasing as zf grows, or G farther from the exact
// 4MSM value than the case's bound. docs/numerics.md explains the cases.
//
// Usage (a GL context must be current, e.g. from createContext):
//     RobustnessReport r = probeMsmRobustness(library);      // library: the student's stages
//     r.score                       // in [0, 1]: the fraction of cases with no problem
//     for (auto& c : r.cases) if (!c.ok()) ... c.input.name, c.input.b, c.input.zf, c.G,
//                                              c.problems(), c.input.expected, c.input.bound
//     r.summary(20)                 // human-readable: the score and up to 20 failing cases
#pragma once

#include "probe_cases.h"
#include "shader_source.h"

#include <string>
#include <vector>

namespace sl {

struct RobustnessCase {
    MsmCase input;           // the case: name, b, zf, expected, bound, note
    float G = 0.0f;          // what the solution returned at input.zf
    bool nan = false, inf = false;
    bool outOfRange = false;   // G < 0 or G > 1
    bool nonMonotone = false;  // along a zf ladder for this b, G drops by more than kMonotoneSlack
    float dropZf0 = 0, dropZf1 = 0, dropG0 = 0, dropG1 = 0;  // the largest such drop: G(zf0) > G(zf1)
    bool offExpected = false;  // |G − expected| > bound (only where expected is finite)
    bool ok() const { return !(nan || inf || outOfRange || nonMonotone || offExpected); }
    std::string problems() const;  // "NaN, non-monotone", or "" when ok
};

struct RobustnessReport {
    std::vector<RobustnessCase> cases;  // every catalogue case, in catalogue order
    int failed = 0;
    double score = 1.0;                 // (cases − failed) / cases
    std::string summary(int maxListed = 20) const;
};

// Rounding may make even a correct float32 4MSM wobble this much as zf grows: more than 10x
// the largest drop of the family of correct variants (7.9e-5, pivot floors at 1e-11; the
// reference 7.1e-6; docs/numerics.md), far below the drops of a broken solve (0.29-1.2).
constexpr float kMonotoneSlack = 1e-3f;

// The fragment depths at which a case is probed for monotonicity: 49 depths evenly in
// [-0.1, 1.1] and the case's own zf, sorted. `shadowlab probe msm --generate zf-ladder`
// writes them for every case, so that a student can reproduce a "non-monotone in zf".
std::vector<float> msmMonotoneLadder(const MsmCase& c);

// Probes `library`'s momentShadowIntensity (uMomentBias = alpha) on the catalogue, in one
// dispatch on the current GL context. Throws ShaderError if msm.glsl does not compile.
RobustnessReport probeMsmRobustness(const ShaderLibrary& library,
                                    float alpha = kReferenceMomentBias);

}  // namespace sl
