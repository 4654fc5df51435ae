// Renderer: runs a PassPlan for a scene on the current GL context and reads back its images:
// each pass with the program it names, on the textures of the roles it names.
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

// What one light's shadow pass(es) wrote, in the map's own format: the plan's "raw" role (the
// technique's map: R32F depth for hard/pcf/pcss/second-depth, RG32F (z, z²) for unfiltered vsm
// (RGBA32F when a filter stage reads it, mapLayout), RGBA32F
// moments for msm4/msm4-hausdorff/evsm4/msm-soft, RGBA16 for msm4-16bit, several RGBA32F
// layers for csm, ...) and, for second-depth, the peeled "second" map. Image channels follow
// the format (Texture::read); RGBA16 values are read as floats k/65535 and upload back to
// the same k, so a map read back and fed in again is bit-identical.
struct RawShadowMap {
    std::vector<Image> raw;  // one image per layer of the "raw" role (1 but for csm)
    Image second;            // second-depth only; empty (0 × 0) for every other technique
    // A directional light with cascades (cascades.h): the members above are cascade 0's,
    // these are cascades 1 .. n-1 (empty without cascades), each with its own `raw`/`second`.
    std::vector<RawShadowMap> cascades;
};

// Maps a render takes from the caller instead of making them, by index into Scene::lights.
struct RenderInputs {
    // An already FILTERED moment map (RGBA32F, the plan's map size): that light's shadow and
    // filter passes are all skipped and lighting samples this map bilinearly, so give the
    // scene the filter `none`. The grader's msm stage feeds the reference's filtered moments
    // to a student's msm.glsl this way.
    std::map<int, Image> filteredMoments;
    // An already RENDERED raw map (RenderResult::rawMaps of an earlier render): that light's
    // shadow pass and second-depth peel are skipped (their passMillis are 0), and its filter
    // passes and lighting run as planned. The map must come from a scene with the same
    // geometry, light, map size and technique format (same `mapLayout`): the shadow map of a
    // (scene, light, size, format) is then rendered once and shared by every technique and
    // filter that reads that format (the technique sweep renders each map once). Sizes, layers and
    // channels are checked (std::invalid_argument); that it is the same scene is the caller's
    // promise.
    std::map<int, RawShadowMap> rawMaps;
    // Per camera (index into Scene::cameras): zf of the first shadowing light at each pixel,
    // the "relative_depth" image of a RelativeDepth::Shown render (R32F, the camera's size).
    // Required by a plan with RelativeDepth::Given, which reads zf from it.
    std::map<int, Image> relativeDepth;
    // Fill RenderResult::rawMaps with every shadowing light's raw map (one extra read-back
    // per light; off by default because a 2048² RGBA32F map is 64 MiB).
    bool keepRawMaps = false;
    // Read the shadow maps back into RenderResult::images (moments_raw, moments_filtered, sat)
    // and look for stub stages there. false: only the cameras' images (a study's frames need
    // only G; a 2048² RGBA32F map is 64 MiB to read, three times a frame).
    bool readMaps = true;
};

struct RenderResult {
    // First shadowing light: "moments_raw", "moments_filtered", and "sat" for a SAT filter;
    // further lights add the suffix "_light<i>". First camera: "shadow" (G) and "final"
    // (colour); further cameras add "_<camera name>". A RelativeDepth::Shown plan gives
    // "relative_depth" in their place.
    std::map<std::string, Image> images;
    std::vector<double> passMillis;     // one per planned pass (glFinish-bounded wall time)
    std::vector<double> passCost;       // the same passes' cost (cost_clock.h: CPU ms, all threads)
    std::vector<std::string> stubNotes; // "student/msm.glsl: momentShadowIntensity: not implemented yet ..."
    // With RenderInputs::keepRawMaps: each shadowing light's raw map, to feed to later renders
    // through RenderInputs::rawMaps (given maps come back as they went in).
    std::map<int, RawShadowMap> rawMaps;
};

class Renderer {
public:
    explicit Renderer(ShaderLibrary library);
    ~Renderer();

    // Runs `plan` (planPasses(scene)) and reads back its images. `inputs`: maps to use
    // instead of rendering them (see RenderInputs). Sharing one shadow map between renders:
    //   RenderInputs keep;  keep.keepRawMaps = true;
    //   RenderResult first = renderer.render(scene, planPasses(scene), keep);
    //   RenderInputs shared;  shared.rawMaps = first.rawMaps;
    //   RenderResult other = renderer.render(sceneWithAnotherFilter, planPasses(...), shared);
    RenderResult render(const Scene& scene, const PassPlan& plan,
                        const RenderInputs& inputs = {});
    // Compiles every program `plan` runs, as its passes will ask for them (render does this
    // first, so that pass times measure rendering, not the driver's compiler).
    void compilePrograms(const Scene& scene, const PassPlan& plan);
    // How many programs are compiled so far (one per files and defines).
    size_t programCount() const { return programs_.size(); }

    // One dispatch each, src -> dst (both RGBA32F, same size). Compile on first use.
    void copyPass(const Texture& src, const Texture& dst);
    // src of any format (sampled) -> dst RGBA32F, same size (shaders/widen.comp).
    void widenPass(const Texture& src, const Texture& dst);
    void gaussianPass(const Texture& src, const Texture& dst, int radius, float sigma,
                      glm::ivec2 direction);
    // One pass of sat.comp. The table (dst; src of the column pass) is satTableWidth(W) × H
    // for a W × H map (pass_plan.h).
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
    // The program a plan's pass names (PlannedPass::program), from the cache.
    GlProgram& program(const PassProgram& description);
    // The program a pass kind runs outside a plan (the passes' public entry points, for the
    // benchmark and the grader): passProgramFor's description.
    GlProgram& passProgram(PassKind kind, int blurRadius, const std::vector<std::string>& defines);
    // The filter passes with the program given (render: the plan's; the public ones above:
    // passProgram's, the same description).
    void widenPass(GlProgram& p, const Texture& src, const Texture& dst);
    void gaussianPass(GlProgram& p, const Texture& src, const Texture& dst, int radius,
                      float sigma, glm::ivec2 direction);
    void satPass(GlProgram& p, const Texture& src, const Texture& dst, glm::ivec2 direction);
    void satResolvePass(GlProgram& p, const Texture& sat, const Texture& dst, float kernelTexels);
    const BufferHandle& weightsBuffer(int radius, float sigma);
    void dispatchLines(const GlProgram& p, glm::ivec2 size, glm::ivec2 direction, bool wholeLine);

    ShaderLibrary library_;
    std::map<std::string, std::unique_ptr<GlProgram>> programs_;
    std::map<std::pair<int, float>, BufferHandle> gaussianWeights_;  // (radius, sigma) -> SSBO
};

}  // namespace sl
