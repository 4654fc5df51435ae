// Renderer::render: allocates what the plan lists, runs its passes in order (timing each) and
// reads the images back. Each pass runs the program the plan names for it, on the textures of
// the roles it names (PlannedPass::program, reads, writes): the renderer decides neither. The
// passes themselves live in scene_passes.cpp (shadow, lighting), filter_passes.cpp (Gaussian,
// SAT), pass_programs.cpp (the program cache) and render_readback.cpp (maps into RenderResult).
#include "render_internal.h"

#include "cascades.h"
#include "cost_clock.h"
#include "scene_limits.h"

#include <chrono>
#include <stdexcept>

namespace sl {
using namespace render_detail;
namespace {

// Sampled maps filter bilinearly (filtering depth or moments is linear); tables do not.
GLenum samplerFilter(TextureRole role) {
    return role == TextureRole::Raw || role == TextureRole::Filtered || role == TextureRole::Second
               ? GL_LINEAR
               : GL_NEAREST;
}

// Uploads the caller's raw map (role "raw": its layers; "second": the peeled map) into the
// textures just allocated for planned texture `t`, after checking that it fits them.
void uploadRawMap(const RawShadowMap& given, const PlannedTexture& t, std::vector<Texture>& layers) {
    std::vector<const Image*> images;
    if (t.role == TextureRole::Raw)
        for (const Image& i : given.raw) images.push_back(&i);
    else
        images.push_back(&given.second);
    auto describe = [](int w, int h, int c) {
        return std::to_string(w) + "x" + std::to_string(h) + "x" + std::to_string(c);
    };
    if (images.size() != layers.size())
        throw std::invalid_argument("RenderInputs::rawMaps: light " + std::to_string(t.light) +
                                    " role " + toString(t.role) + ": expected " +
                                    std::to_string(layers.size()) + " layer(s), found " +
                                    std::to_string(images.size()));
    for (size_t k = 0; k < layers.size(); ++k) {
        const Image& i = *images[k];
        try {
            layers[k].upload(i);  // checks the size and the format's channel count
        } catch (const std::invalid_argument&) {
            throw std::invalid_argument("RenderInputs::rawMaps: light " + std::to_string(t.light) +
                                        " role " + toString(t.role) + ": expected a " + t.format + " map " +
                                        std::to_string(t.width) + "x" + std::to_string(t.height) +
                                        ", found " + describe(i.width, i.height, i.channels));
        }
    }
}

}  // namespace

Renderer::Renderer(ShaderLibrary library) : library_(std::move(library)) {}
Renderer::~Renderer() = default;

RenderResult Renderer::render(const Scene& scene, const PassPlan& plan,
                              const RenderInputs& inputs) {
    if (scene.lights.size() > size_t(kMaxLights))  // the loader refuses such a scene first
        throw std::runtime_error(scene.path + ": at most " + std::to_string(kMaxLights) + " lights");
    RenderResult result;
    SceneGeometry geometry(scene);
    const ShadowEffect& fx = plan.effect;  // the plan decided; the renderer executes
    const TechniqueRow& row = *plan.row;

    std::vector<LightView> views;
    for (const Light& light : scene.lights)
        views.push_back(computeLightView(light, fx, geometry.bounds()));
    // Allocate what the plan lists, and nothing else.
    ShadowMapSet maps;
    for (int li : plan.shadowLights) maps[{li, 0}].view = views[li];
    for (const PlannedCascade& c : plan.cascades) {
        ShadowMaps& m = maps[{c.light, c.cascade}];
        float halfWidth = 0.0f;
        m.view = fitCascade(views[c.light], scene.cameras.front(), c.nearDepth, c.farDepth,
                            fx.mapSize, &halfWidth);
        m.frustumWidth = 2.0f * halfWidth;
    }
    for (const PlannedTexture& t : plan.textures) {
        if (t.light < 0) continue;
        ShadowMaps& m = maps[{t.light, t.cascade}];
        auto& layers = m.tex[t.role];
        const auto filtered = inputs.filteredMoments.find(t.light);
        if (t.role == TextureRole::Raw && filtered != inputs.filteredMoments.end()) {
            if (plan.cascadeCount(t.light) > 1)
                throw std::invalid_argument("RenderInputs::filteredMoments: light " +
                                            std::to_string(t.light) + " has cascades");
            const Image& given = filtered->second;
            layers.push_back(Texture::create(given.width, given.height, GL_RGBA32F, GL_LINEAR));
            layers.back().upload(given);
            m.given = true;
            continue;
        }
        for (int k = 0; k < t.layers; ++k)
            layers.push_back(Texture::create(t.width, t.height, t.glFormat, samplerFilter(t.role)));
        const auto raw = inputs.rawMaps.find(t.light);
        if (raw != inputs.rawMaps.end() && (t.role == TextureRole::Raw || t.role == TextureRole::Second)) {
            const RawShadowMap& all = raw->second;
            if (t.cascade > int(all.cascades.size()))
                throw std::invalid_argument("RenderInputs::rawMaps: light " +
                                            std::to_string(t.light) + ": no map for cascade " +
                                            std::to_string(t.cascade));
            uploadRawMap(t.cascade == 0 ? all : all.cascades[t.cascade - 1], t, layers);
            m.givenRaw = true;
        }
    }
    const std::vector<glm::vec4> clear = shadowClearValues(fx);

    struct CameraTargets { Texture color, shadow, depth; };
    std::map<int, CameraTargets> targets;

    // The caller's filtered moments stand in for all of a light's passes, its raw map for its
    // shadow passes: those never run, and their programs are not compiled (the grader's msm
    // stage must not compile the submission's moments.glsl through the shadow pass).
    auto standsIn = [&](const PlannedPass& pass) {
        const ShadowMaps* m = pass.light >= 0 ? &maps.at({pass.light, pass.cascade}) : nullptr;
        const bool shadowPass = pass.kind == PassKind::Shadow || pass.kind == PassKind::ShadowSecond;
        return m && (m->given || (m->givenRaw && shadowPass));
    };
    // Every program first, so that pass times measure rendering, not the compiler.
    for (const PlannedPass& pass : plan.passes)
        if (!standsIn(pass)) program(pass.program);

    gl::Enable(GL_DEPTH_TEST);
    gl::DepthFunc(GL_LESS);
    for (const PlannedPass& pass : plan.passes) {
        const auto start = std::chrono::steady_clock::now();
        costBegin();
        ShadowMaps* m = pass.light >= 0 ? &maps.at({pass.light, pass.cascade}) : nullptr;
        if (standsIn(pass)) {
            result.passMillis.push_back(0.0);
            result.passCost.push_back(0.0);
            continue;
        }
        GlProgram& prog = program(pass.program);
        // A filter pass's layers: its one input role and its output role, as the plan says.
        auto src = [&]() -> std::vector<Texture>& { return m->tex.at(pass.reads.at(0)); };
        auto dst = [&]() -> std::vector<Texture>& { return m->tex.at(pass.writes); };
        const glm::ivec2 along = pass.kind == PassKind::GaussianX || pass.kind == PassKind::SatRows
                                     ? glm::ivec2(1, 0)
                                     : glm::ivec2(0, 1);
        switch (pass.kind) {
            case PassKind::Shadow:
            case PassKind::ShadowSecond:
                runShadowPass(prog, pass, *m, clear, fx, geometry);
                break;
            case PassKind::Widen:
                for (size_t k = 0; k < src().size(); ++k) widenPass(prog, src()[k], dst()[k]);
                break;
            case PassKind::GaussianX:
            case PassKind::GaussianY:
                for (size_t k = 0; k < src().size(); ++k)
                    gaussianPass(prog, src()[k], dst()[k], fx.gaussianRadius, fx.gaussianSigma, along);
                break;
            case PassKind::SatRows:
            case PassKind::SatColumns:
                for (size_t k = 0; k < src().size(); ++k) satPass(prog, src()[k], dst()[k], along);
                break;
            case PassKind::SatResolve:
                for (size_t k = 0; k < src().size(); ++k)
                    satResolvePass(prog, src()[k], dst()[k], fx.satKernelTexels);
                break;
            case PassKind::Lighting: {
                // What lighting samples of each light: the pass's roles, in unit order; a
                // filtered map given by the caller stands in for them.
                for (auto& [id, lightMaps] : maps) {
                    lightMaps.forLighting.clear();
                    const std::vector<TextureRole> given = {TextureRole::Raw};
                    for (TextureRole role : lightMaps.given ? given : pass.reads)
                        for (const Texture& layer : lightMaps.tex.at(role)) lightMaps.forLighting.push_back(&layer);
                }
                CameraTargets& t = targets[pass.camera];
                Texture given;
                if (plan.relativeDepth == RelativeDepth::Given) {
                    const auto it = inputs.relativeDepth.find(pass.camera);
                    if (it == inputs.relativeDepth.end())
                        throw std::invalid_argument("RenderInputs::relativeDepth: no image for camera " +
                                                    std::to_string(pass.camera));
                    given = Texture::create(it->second.width, it->second.height, GL_R32F, GL_NEAREST);
                    given.upload(it->second);
                }
                runLightingPass(prog, scene, plan, scene.cameras.at(pass.camera), views, maps,
                                geometry, t.color, t.shadow, t.depth,
                                plan.relativeDepth == RelativeDepth::Given ? &given : nullptr);
                break;
            }
        }
        gl::Finish();
        result.passMillis.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
        result.passCost.push_back(costEnd());
    }
    if (inputs.readMaps) readBack(library_, row, fx, plan, maps, result);
    if (inputs.keepRawMaps)
        for (auto& [id, m] : maps) {  // in (light, cascade) order
            if (m.given) continue;  // a filtered map stood in: there is no raw map
            RawShadowMap& light = result.rawMaps[id.light];
            RawShadowMap& out = id.cascade == 0 ? light : light.cascades.emplace_back();
            for (const Texture& t : m.tex.at(TextureRole::Raw)) out.raw.push_back(t.read());
            if (m.tex.count(TextureRole::Second)) out.second = m.one(TextureRole::Second).read();
        }
    for (const auto& [ci, t] : targets) {
        const std::string suffix = ci == 0 ? "" : "_" + scene.cameras[ci].name;
        Image shadow = t.shadow.read();
        if (plan.relativeDepth == RelativeDepth::Shown) {
            result.images["relative_depth" + suffix] = std::move(shadow);
            continue;
        }
        if (!maps.empty()) noteLightingStubs(library_, row, shadow, result);
        Image color = t.color.read();
        Image rgb(color.width, color.height, 3);
        for (size_t i = 0, count = size_t(color.width) * color.height; i < count; ++i)
            for (int c = 0; c < 3; ++c) rgb.pixels[i * 3 + c] = color.pixels[i * 4 + c];
        result.images["shadow" + suffix] = std::move(shadow);
        result.images["final" + suffix] = std::move(rgb);
    }
    return result;
}

}  // namespace sl
