// probe: evaluates a stage function on arbitrary inputs in one compute dispatch on the current
// context, with exactly the GLSL the renderer compiles. Unit tests for shaders, for the
// students, the tests and the grader alike.
#pragma once

#include "shader_source.h"

#include <glm/glm.hpp>

#include <vector>

namespace sl {

// G = momentShadowIntensity(b[i], zf[i]) with uMomentBias = momentBias.
std::vector<float> probeMomentShadowIntensity(const ShaderLibrary& library,
                                              const std::vector<glm::vec4>& b,
                                              const std::vector<float>& zf, float momentBias);

// computeMoments(relativeDepth(lightDepth, (near, far))) per input (lightDepth, near, far).
std::vector<glm::vec4> probeMoments(const ShaderLibrary& library,
                                    const std::vector<glm::vec3>& inputs);

}  // namespace sl
