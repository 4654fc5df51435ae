// probe_cases: the named input sets of `shadowlab probe --generate NAME`, above all the
// hard-case catalogue of momentShadowIntensity (docs/numerics.md), each case with its exact
// expected value and the bound a float32 implementation must meet.
//
// Expected values come from exactMomentShadowIntensity (msm_exact.h, long double); for point
// masses that is also the analytic CDF (tests/test_numerics_catalogue.cpp checks both agree).
// Bounds: 2e-4 + 4·msmFloatSensitivity, i.e. what float32 rounding of the inputs can move G.
#pragma once

#include "msm_exact.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace sl {

// The reference's moment bias α and the vector it biases toward (reference/msm.glsl).
constexpr float kReferenceMomentBias = 3e-5f;
constexpr float kMomentBiasTarget = 0.5f;  // b' = (1 - α)·b + α·(0.5, 0.5, 0.5, 0.5)

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
