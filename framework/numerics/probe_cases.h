// probe_cases: the named input sets of `shadowlab probe --generate NAME`, above all the
// hard-case catalogue of momentShadowIntensity (docs/numerics.md), each case with its exact
// expected value and the bound a float32 implementation must meet.
//
// Expected values come from exactMomentShadowIntensity (msm_exact.h, long double); for point
// masses that is also the analytic CDF (tests/test_numerics_catalogue.cpp checks both agree).
// Bounds: kMsmAbsoluteBound + 4·msmFloatSensitivity: what float32 rounding of the inputs can
// move G (the sensitivity term, large where G jumps), plus what correct float32 formulas
// differ by on top of that (docs/numerics.md, "The robustness bound").
#pragma once

#include "msm_exact.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace sl {

// The reference's moment bias α and the vector it biases toward (reference/msm.glsl).
constexpr float kReferenceMomentBias = 3e-5f;
constexpr float kMomentBiasTarget = 0.5f;  // b' = (1 - α)·b + α·(0.5, 0.5, 0.5, 0.5)

// The absolute part of every hard case's bound: twice the largest deviation from the exact
// value found in the family of correct variants (tests/submissions/alternatives/msm_*: 5.0e-3,
// the textbook quadratic formula at c3 ≈ 0), and half the msm stage's image tolerance (0.02),
// so a deviation this small cannot show in the graded shadows either.
constexpr double kMsmAbsoluteBound = 1e-2;

struct MsmCase {
    std::string set;     // case set, e.g. "two-point"
    std::string name;    // unique label, e.g. "two-point/z0.3,0.7/zf0.5"
    glm::vec4 b{};       // exactly what the shader is given
    float zf = 0.0f;
    double expected = 0; // exact 4MSM of (b, zf) at α; NaN: b is no valid moment vector
    double bound = 0;    // |G − expected| a float32 implementation must meet
    std::string note;    // the math of the case in one line
};

// Names of the momentShadowIntensity case sets, in catalogue order.
const std::vector<std::string>& msmCaseSetNames();

// One set (throws std::invalid_argument naming the known sets for an unknown name), or all.
std::vector<MsmCase> msmCaseSet(const std::string& set, float alpha = kReferenceMomentBias);
std::vector<MsmCase> msmHardCaseCatalogue(float alpha = kReferenceMomentBias);

}  // namespace sl
