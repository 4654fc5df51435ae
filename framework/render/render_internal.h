// Internal to the renderer's files (renderer.cpp, scene_passes.cpp, render_readback.cpp, ...): the
// per-light textures a render allocates and the helpers its stages share. Not a public API.
#pragma once

#include "gl_program.h"
#include "gpu_resources.h"
#include "light_view.h"
#include "renderer.h"
#include "scene_geometry.h"
#include "stage_functions.h"
#include "technique.h"

#include <map>
#include <string>
#include <vector>

namespace sl::render_detail {

// The textures of one shadowing light, by role (pass_plan.h), each a list of layers.
struct ShadowMaps {
    std::map<TextureRole, std::vector<Texture>> tex;
    bool given = false;     // filtered moments came from the caller: no shadow or filter pass runs
    bool givenRaw = false;  // the raw map came from the caller: no shadow pass runs
    LightView view;
    std::vector<const Texture*> forLighting;  // what lighting samples, in unit order
    Texture& one(TextureRole role) { return tex.at(role).front(); }
    float frustumWidth = 0.0f;  // a cascade's: its window's width, world units (0: the light's)
};

// A light's maps, one set per cascade (cascade 0 only without cascades).
struct ShadowMapId {
    int light = 0;
    int cascade = 0;
    auto operator<=>(const ShadowMapId&) const = default;
};
using ShadowMapSet = std::map<ShadowMapId, ShadowMaps>;

// A framebuffer with `colors` as its draw buffers, in order, and `depth` as its depth.
FramebufferHandle makeFramebuffer(const std::vector<const Texture*>& colors, const Texture& depth);

// True if `out` holds the stub value -1 at a texel where `in` (same size) does not; with
// `everywhere`, true if every texel of `out` holds it.
bool stubOutput(const Image& out, const Image* in, bool everywhere = false);
// Adds "<file>: <function>: not implemented yet ..." to the result's notes, once.
void noteStub(const ShaderLibrary& library, RenderResult& result, StageFunction function);

// Reads the maps back into `result`, and tells unimplemented stages apart from wrong ones by
// the stub value.
void readBack(const ShaderLibrary& library, const TechniqueRow& row, const ShadowEffect& fx,
              const PassPlan& plan, ShadowMapSet& maps, RenderResult& result);
// The stubs the lighting pass shows in the first light's G (`shadow`): -1 from msm.glsl's
// momentShadowIntensity, -2 where relativeDepth returned its stub value, -3 both (lighting.frag).
void noteLightingStubs(const ShaderLibrary& library, const TechniqueRow& row, const Image& shadow,
                       RenderResult& result);

// The shadow pass (or the second-depth peel) of one light, with program `p`: draws into the
// layers of the role `pass` writes with its depth role, the roles it reads bound in order.
void runShadowPass(GlProgram& p, const PlannedPass& pass, ShadowMaps& m,
                   const std::vector<glm::vec4>& clear, const ShadowEffect& fx,
                   const SceneGeometry& geometry);

// The lighting pass of camera `cam` into `color`/`shadow`/`depth` (created here), with program
// `p` and every light's maps (every cascade's) bound as the lighting samples them; `plan`
// gives the cascades' depth ranges.
// givenRelativeDepth: the camera's zf image (RelativeDepth::Given), else null.
void runLightingPass(GlProgram& p, const Scene& scene, const PassPlan& plan, const Camera& cam,
                     const std::vector<LightView>& views, ShadowMapSet& maps,
                     const SceneGeometry& geometry, Texture& color,
                     Texture& shadow, Texture& depth, const Texture* givenRelativeDepth);

// Dispatches `p` over a `size` image whose invocations each write uTexelsPerInvocation
// consecutive texels along `direction` (docs/stage_contract.md, "Invocation mapping"), then a
// barrier; filter_passes.cpp. The Gaussians and the bench's tiled copy.
void dispatchTexelRuns(const GlProgram& p, glm::ivec2 size, glm::ivec2 direction);

}  // namespace sl::render_detail
