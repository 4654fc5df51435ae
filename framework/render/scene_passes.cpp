// Renderer's scene passes: the shadow pass that rasterises the casters into a light's maps,
// and the lighting pass that shades a camera's view from every light's (filtered) maps.
#include "render_internal.h"

#include "scene_limits.h"

#include <cctype>
#include <cmath>
#include <stdexcept>

namespace sl::render_detail {
namespace {

// A technique's parameters as the uniforms u<Name> (the shadow pass's warps, the lighting's).
void setTechniqueParameters(const GlProgram& p, const ShadowEffect& fx) {
    for (const auto& [name, value] : resolvedParameters(fx)) {
        const std::string uniform = "u" + std::string(1, char(std::toupper(name[0]))) + name.substr(1);
        p.set(uniform.c_str(), float(value));
    }
}

// The uniforms of a technique's lighting permutation: its parameters as u<Name>,
// the sampler units, the map size and the Gaussian weights (PCF uses the moment filter's).
void setTechniqueUniforms(const GlProgram& p, const ShadowEffect& fx, int unitsUsed) {
    constexpr int kMaxMaps = kMaxShadowMaps;  // SL_MAX_MAPS in the shaders
    if (unitsUsed > kMaxMaps)
        throw std::runtime_error("the shadow maps need " + std::to_string(unitsUsed) +
                                 " texture units; the lighting pass has " +
                                 std::to_string(kMaxMaps));
    std::vector<int> units(kMaxMaps);
    for (int i = 0; i < kMaxMaps; ++i) units[i] = i;
    p.setArray("uShadowMaps", units);
    p.set("uMapTexels", glm::vec2(float(fx.mapSize)));
    setTechniqueParameters(p, fx);
    std::vector<float> w = Renderer::gaussianWeights(fx.gaussianRadius, fx.gaussianSigma);
    p.set("uGaussianRadius", fx.gaussianRadius);
    p.setArray("uGaussianWeights", w);
}

}  // namespace

FramebufferHandle makeFramebuffer(const std::vector<const Texture*>& colors, const Texture& depth) {
    GLuint id = 0;
    gl::CreateFramebuffers(1, &id);
    FramebufferHandle fb(id);
    std::vector<GLenum> buffers;
    for (size_t i = 0; i < colors.size(); ++i) {
        gl::NamedFramebufferTexture(id, GLenum(GL_COLOR_ATTACHMENT0 + i), colors[i]->id(), 0);
        buffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
    }
    gl::NamedFramebufferTexture(id, GL_DEPTH_ATTACHMENT, depth.id(), 0);
    gl::NamedFramebufferDrawBuffers(id, GLsizei(buffers.size()), buffers.data());
    if (gl::CheckNamedFramebufferStatus(id, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("framebuffer incomplete");
    return fb;
}

void runShadowPass(GlProgram& p, const PlannedPass& pass, ShadowMaps& m,
                   const std::vector<glm::vec4>& clear, const ShadowEffect& fx,
                   const SceneGeometry& geometry) {
    const int n = fx.mapSize;
    std::vector<const Texture*> colors;
    for (const Texture& t : m.tex.at(pass.writes)) colors.push_back(&t);
    FramebufferHandle fb = makeFramebuffer(colors, m.one(pass.depth.value()));
    const float farDepth = 1.0f;
    for (size_t k = 0; k < colors.size(); ++k) {
        // Relative depth 1 everywhere: nothing in front (msm4: moments (1, 1, 1, 1)); the
        // second depth's midpoint likewise.
        const glm::vec4 c = pass.writes == TextureRole::Raw ? clear[k] : glm::vec4(1.0f);
        gl::ClearNamedFramebufferfv(fb.id(), GL_COLOR, GLint(k), &c.x);
    }
    gl::ClearNamedFramebufferfv(fb.id(), GL_DEPTH, 0, &farDepth);
    gl::BindFramebuffer(GL_FRAMEBUFFER, fb.id());
    gl::Viewport(0, 0, n, n);
    p.use();
    p.set("uViewProjection", m.view.viewProjection);
    p.set("uLightEye", m.view.eye);
    p.set("uLightForward", m.view.forward);
    p.set("uDepthRange", m.view.depthRange);
    setTechniqueParameters(p, fx);
    if (pass.kind == PassKind::ShadowSecond) {
        p.set("uPeelEpsilon", float(techniqueParameter(fx, "peelEpsilon")));
        p.set("uFirstDepth", 0);
    }
    // What the pass reads (the peel: the first surface's depth), at units 0, 1, ...
    for (size_t unit = 0; unit < pass.reads.size(); ++unit)
        gl::BindTextureUnit(GLuint(unit), m.one(pass.reads[unit]).id());
    geometry.draw(p, true, false);
    gl::BindFramebuffer(GL_FRAMEBUFFER, 0);
}

void runLightingPass(GlProgram& p, const Scene& scene, const PassPlan& plan, const Camera& cam,
                     const std::vector<LightView>& views, ShadowMapSet& maps,
                     const SceneGeometry& geometry, Texture& colorTarget,
                     Texture& shadowTarget, Texture& depthTarget,
                     const Texture* givenRelativeDepth) {
    const ShadowEffect& fx = plan.effect;
    colorTarget = Texture::create(cam.width, cam.height, GL_RGBA32F);
    shadowTarget = Texture::create(cam.width, cam.height, GL_R32F);
    depthTarget = Texture::create(cam.width, cam.height, GL_DEPTH_COMPONENT32F);
    FramebufferHandle fb = makeFramebuffer({&colorTarget, &shadowTarget}, depthTarget);
    const float bg[4] = {scene.background.x, scene.background.y, scene.background.z, 1};
    const float zero[4] = {0, 0, 0, 0};
    const float farDepth = 1.0f;
    gl::ClearNamedFramebufferfv(fb.id(), GL_COLOR, 0, bg);
    gl::ClearNamedFramebufferfv(fb.id(), GL_COLOR, 1, zero);
    gl::ClearNamedFramebufferfv(fb.id(), GL_DEPTH, 0, &farDepth);
    gl::BindFramebuffer(GL_FRAMEBUFFER, fb.id());
    gl::Viewport(0, 0, cam.width, cam.height);
    p.use();
    CameraView cv = computeCameraView(cam);
    p.set("uViewProjection", cv.viewProjection);
    p.set("uCameraPosition", cam.position);
    p.set("uAmbient", scene.ambient);
    p.set("uMomentBias", fx.momentBias);
    p.set("uDepthBias", fx.depthBias);
    p.set("uSatKernel", fx.satKernelTexels);
    p.set("uSatSearchTexels", fx.satKernelTexels);  // per-pixel: the search box's limit
    p.set("uSatMaxKernel", fx.satMaxKernelTexels);
    constexpr int kSlots = kMaxLights * kMaxCascades;  // SL_MAX_LIGHTS · SL_MAX_CASCADES
    std::vector<glm::vec3> eye, forward, color;
    std::vector<int> isSpot, mapIndex, cascades, units(kSlots);
    for (int k = 0; k < kSlots; ++k) units[k] = k;
    std::vector<float> cosHalfCone, lightSize;
    std::vector<glm::vec2> range;
    std::vector<glm::vec4> cascadeFar;
    // Per slot (light i, cascade c at kMaxCascades·i + c): light view, first map, frustum width.
    std::vector<glm::mat4> slotViewProj(kSlots, glm::mat4(1.0f));
    std::vector<int> slotMap(kSlots, -1);
    std::vector<float> slotFrustum(kSlots, 0.0f);
    int unit = 0;
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& l = scene.lights[i];
        eye.push_back(views[i].eye);
        forward.push_back(views[i].forward);
        color.push_back(l.color * l.intensity);
        isSpot.push_back(l.type == LightType::Spot);
        cosHalfCone.push_back(std::cos(glm::radians(l.coneDegrees * 0.5f)));
        range.push_back(views[i].depthRange);
        lightSize.push_back(l.size);
        // Width of the shadow frustum: spot: × the depth; directional: as is.
        const float frustum = l.type == LightType::Spot
                                  ? 2.0f * std::tan(glm::radians(l.coneDegrees * 0.5f))
                                  : 2.0f * l.extent;
        const int n = plan.cascadeCount(int(i));
        cascades.push_back(n);
        glm::vec4 far(1e30f);
        for (const PlannedCascade& c : plan.cascades)
            if (c.light == int(i)) far[c.cascade] = c.farDepth;
        cascadeFar.push_back(far);
        const int first = kMaxCascades * int(i);
        slotViewProj[first] = views[i].viewProjection;
        slotFrustum[first] = frustum;
        mapIndex.push_back(maps.count({int(i), 0}) ? unit : -1);
        for (int c = 0; c < n; ++c) {
            auto it = maps.find({int(i), c});
            if (it == maps.end()) continue;
            const ShadowMaps& m = it->second;
            slotViewProj[first + c] = m.view.viewProjection;
            if (m.frustumWidth > 0.0f) slotFrustum[first + c] = m.frustumWidth;
            slotMap[first + c] = unit;
            for (const Texture* tex : m.forLighting) gl::BindTextureUnit(GLuint(unit++), tex->id());
        }
    }
    p.set("uLightCount", int(scene.lights.size()));
    p.setArray("uLightEye", eye);
    p.setArray("uLightForward", forward);
    p.setArray("uLightColor", color);
    p.setArray("uLightIsSpot", isSpot);
    p.setArray("uLightCosHalfCone", cosHalfCone);
    p.setArray("uLightShadowMap", mapIndex);
    p.setArray("uLightDepthRange", range);
    p.setArray("uLightCascades", cascades);
    p.setArray("uLightCascadeFar", cascadeFar);
    p.setArray("uSlotViewProjection", slotViewProj);
    p.setArray("uSlotShadowMap", slotMap);
    const Camera& fitted = scene.cameras.front();  // the cascades are fitted to it
    p.set("uCascadeCameraPosition", fitted.position);
    p.set("uCascadeCameraForward", glm::normalize(fitted.target - fitted.position));
    setTechniqueUniforms(p, fx, unit);
    if (givenRelativeDepth) {  // after the maps' sampler array (units 0 .. kMaxShadowMaps - 1)
        gl::BindTextureUnit(GLuint(kMaxShadowMaps), givenRelativeDepth->id());
        p.set("uGivenRelativeDepth", kMaxShadowMaps);
        p.set("uFirstShadowLight", plan.shadowLights.empty() ? -1 : plan.shadowLights.front());
    }
    p.setArray("uLightSize", lightSize);
    p.setArray("uSlotFrustumScale", slotFrustum);
    geometry.draw(p, false, true);
    gl::BindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace sl::render_detail
