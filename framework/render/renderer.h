// Renderer: runs a PassPlan for a scene on the current GL context and reads back its images.
// The passes are the building blocks too: the benchmark and the grader call them directly.
#pragma once

#include "gl_program.h"
#include "gpu_resources.h"
#include "image.h"
#include "pass_plan.h"
#include "scene.h"
#include "shader_source.h"

#include <glm/glm.hpp>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace sl {

struct RenderResult {
    // First shadowing light: "moments_raw", "moments_filtered", and "sat" for a SAT filter;
    // further lights add the suffix "_light<i>". First camera: "shadow" (G) and "final"
    // (colour); further cameras add "_<camera name>".
    std::map<std::string, Image> images;
    std::vector<double> passMillis;     // one per planned pass (glFinish-bounded wall time)
    std::vector<std::string> stubNotes; // "student/msm.glsl: momentShadowIntensity: not implemented yet ..."
};

class Renderer {
public:
    explicit Renderer(ShaderLibrary library);
    ~Renderer();

    // `moments`: light index -> a moment map to light with instead of rendering and filtering
    // that light's shadow map (its shadow and filter passes are skipped; the map is sampled
    // bilinearly, so give the scene filter `none`). The grader's msm stage uses it to feed the
    // reference's filtered moments to a student's msm.glsl.
    RenderResult render(const Scene& scene, const PassPlan& plan,
                        const std::map<int, Image>* moments = nullptr);

    // One dispatch each, src -> dst (both RGBA32F, same size). Compile on first use.
    void copyPass(const Texture& src, const Texture& dst);
    void gaussianPass(const Texture& src, const Texture& dst, int radius, float sigma,
                      glm::ivec2 direction);
    void satPass(const Texture& src, const Texture& dst, glm::ivec2 direction);
    void satResolvePass(const Texture& sat, const Texture& dst, float kernelTexels);

    const ShaderLibrary& library() const { return library_; }

    // The normalised one-sided weights handed to gaussian_blur.comp: w[0..r],
    // w_k ∝ exp(-k² / 2σ²), w0 + 2·Σ w_k = 1; sigma <= 0 means r / 2.
    static std::vector<float> gaussianWeights(int radius, float sigma);

private:
    // One compiled program per (files, defines), built on first use.
    GlProgram& program(const std::string& vertexOrCompute, const std::string& fragment,
                       const std::vector<std::string>& defines);
    // The program a pass kind runs: the one place that names its files and permutation.
    // `blurRadius`: Gaussian passes; `defines`: the technique/filter ones of the scene.
    GlProgram& passProgram(PassKind kind, int blurRadius, const std::vector<std::string>& defines);
    // The framework's programs of the techniques other than msm4 (shaders/techniques/): their
    // maps are not RGBA32F, so the student's filter stages cannot run on them.
    GlProgram& techniqueProgram(PassKind kind, bool studentStages, unsigned mapFormat,
                                const std::vector<std::string>& defines);
    // Any map format: the same Gaussian weights as gaussianPass, src -> dst.
    void techniqueGaussianPass(const Texture& src, const Texture& dst, int radius, float sigma,
                               glm::ivec2 direction);
    // The SAT as double-float pairs: rows from `src` into (hi, lo); columns in place.
    void techniqueSatPass(const Texture& src, const Texture& hi, const Texture& lo,
                          glm::ivec2 direction);
    const BufferHandle& weightsBuffer(int radius, float sigma);
    void dispatchLines(const GlProgram& p, glm::ivec2 size, glm::ivec2 direction, bool wholeLine);

    ShaderLibrary library_;
    std::map<std::string, std::unique_ptr<GlProgram>> programs_;
    std::map<std::pair<int, float>, BufferHandle> gaussianWeights_;  // (radius, sigma) -> SSBO
};

}  // namespace sl
