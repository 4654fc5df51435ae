// probe: evaluates a stage function on arbitrary inputs in one compute dispatch on the current
// context, with exactly the GLSL the renderer compiles. Unit tests for shaders, for the
// students, the tests and the grader alike.
#pragma once

#include "image.h"
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

// relativeDepth(lightDepth, (near, far)) alone per input (lightDepth, near, far).
std::vector<float> probeRelativeDepth(const ShaderLibrary& library,
                                      const std::vector<glm::vec3>& inputs);

// What the solution's sat.comp makes of `moments` (RGBA, bottom row first) in its two passes:
// the 2W × H table, as the lighting pass reads it.
Image probeSatTableImage(const ShaderLibrary& library, const Image& moments);

// satBoxAverage(table, box.xy = centre, box.zw = size), in texel units, where `table` is what
// the solution's sat.comp makes of `moments` (RGBA, bottom row first, as Image stores it) in
// its two passes. Tests the sat.comp + sat_lookup.glsl pair, as the contract grades it.
std::vector<glm::vec4> probeSatBoxAverage(const ShaderLibrary& library, const Image& moments,
                                          const std::vector<glm::vec4>& boxes);

// One receiver of satKernelTexels (sat_lookup.glsl): its arguments besides the table.
struct SatKernelCase {
    glm::vec2 center{0.0f};   // texel units
    float searchTexels = 1.0f;
    float zr = 0.0f;          // relative depth
    glm::vec2 depthRange{0.0f, 1.0f};
    float lightTexels = 0.0f;
    bool perspective = true;
    glm::vec2 kernelRange{1.0f, 64.0f};
};

// satKernelTexels(table, case...) per case, where `table` is what the solution's sat.comp
// makes of `moments` (as probeSatBoxAverage).
std::vector<float> probeSatKernelTexels(const ShaderLibrary& library, const Image& moments,
                                        const std::vector<SatKernelCase>& cases);

// What the solution's gaussian_blur.comp makes of `map` (RGBA, bottom row first): the pass
// along x if alongX, then the pass along y if alongY, each the renderer's own dispatch with
// the renderer's weights (Renderer::gaussianWeights(radius, sigma)).
Image probeGaussianBlur(const ShaderLibrary& library, const Image& map, int radius, float sigma,
                        bool alongX, bool alongY);

}  // namespace sl
