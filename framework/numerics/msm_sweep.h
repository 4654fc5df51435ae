// msm_sweep: the property sweep of momentShadowIntensity (docs/numerics.md, "Properties over
// 10⁶ generated cases"): random depth distributions (mixtures of point masses and uniform
// intervals in [0, 1], a quarter of them perturbed adversarially), each at 4 sorted fragment
// depths, and the checks that need no 4MSM solver, so that any solution can be swept with
// `shadowlab probe msm --sweep` (the student kit has no exact solver; the instructor's test
// tests/test_numerics_sweep.cpp adds the exact value and the float mirror).
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace sl {

constexpr int kMsmSweepVectors = 250000, kMsmSweepDepthsPerVector = 4;
constexpr uint64_t kMsmSweepSeed = 20150225;

struct MsmSweepCases {
    std::vector<glm::vec4> b;     // per case (kMsmSweepDepthsPerVector cases per vector)
    std::vector<float> zf;        // per case; sorted within each vector
    std::vector<float> minDepth;  // per vector: the nearest occluder depth
    std::vector<char> perturbed;  // per vector: pushed by up to ±64 ulp or ±1e-6 per channel
};

// `vectors` moment vectors, each at 4 fragment depths, the first 0.01 … 0.06 in front of the
// nearest occluder. The same seed gives the same cases.
MsmSweepCases generateMsmSweep(int vectors = kMsmSweepVectors, uint64_t seed = kMsmSweepSeed);

// Stated bounds of the checks (docs/numerics.md). Monotone: G may drop by kMonotoneSlack
// (1e-3, the robustness stage's: msm_robustness.h) along zf; the report gives the largest drop.
constexpr float kSweepFrontMargin = 0.01f;    // "in front of every occluder": by this much
constexpr float kSweepFrontMax = 1e-4f;       // ... where G must stay below this
// Against the two-moment (Cantelli) bounds, on top of any bias target: float rounding.
constexpr double kSweepCantelliSlack = 1e-3;

// The sharp bounds on P(z < zf) that the mean and variance alone give (one-sided Chebyshev,
// Cantelli), widened to hold for any moment bias of weight alpha toward a distribution on
// [-1, 1]: every 4MSM value of a valid moment vector lies in [lower, upper] (4MSM is the
// smallest P(z < zf) over the distributions with all four moments, so it lies between the
// bounds that two of them give).
struct CantelliBounds {
    double lower = 0.0, upper = 1.0;
};
CantelliBounds msmCantelliBounds(glm::vec4 b, float zf, float alpha);

// Which checks a case fails (one per failure kind).
struct MsmSweepProblem {
    size_t index;      // the case
    std::string what;  // "not in [0,1]", "non-monotone", "in front", "below Cantelli", "above Cantelli"
    double bound;      // the value it crossed (the previous G for non-monotone)
};

struct MsmSweepReport {
    size_t cases = 0, vectors = 0, checkedFront = 0, checkedCantelli = 0;
    size_t notInRange = 0, nonMonotone = 0, frontLeak = 0, belowCantelli = 0, aboveCantelli = 0;
    double worstDrop = 0, worstFront = 0, worstCantelli = 0;  // the largest G drop, G in front, distance past a bound
    bool stub = false;                      // every G is the stub value -1 (checks skipped)
    std::vector<MsmSweepProblem> problems;  // every failure, in case order
    size_t failures() const { return notInRange + nonMonotone + frontLeak + belowCantelli + aboveCantelli; }
};

// Checks G (per case of `cases`) against the bounds above: finite and in [0, 1]; monotone
// non-decreasing along each vector's fragment depths (slack kMonotoneSlack); at most
// kSweepFrontMax where zf is kSweepFrontMargin in front of every occluder; within the Cantelli
// bounds (slack kSweepCantelliSlack). The last two on unperturbed vectors only: a perturbed one
// may leave the moment space, where only range and monotonicity are asked.
MsmSweepReport checkMsmSweep(const MsmSweepCases& cases, const std::vector<float>& g, float alpha);

// The summary `probe msm --sweep` prints: what was checked, the count per check, and the first
// `listed` failures with their inputs (lines ending in a newline).
std::string msmSweepSummary(const MsmSweepReport& report, const MsmSweepCases& cases,
                            const std::vector<float>& g, float alpha, size_t listed = 12);

}  // namespace sl
