// Renderer: executes the planned passes (see renderer.h).
#include "renderer.h"

#include "light_view.h"
#include "scene_geometry.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace sl {
namespace {

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

// The textures of one shadowing light.
struct ShadowMaps {
    Texture raw, scratch, filtered, sat, depth;
    bool given = false;  // raw came from the caller: no shadow or filter pass runs
    LightView view;
    const Texture* forLighting = nullptr;  // what lighting samples
};

bool isStubTexel(const Image& img, int x, int y) {
    for (int c = 0; c < img.channels; ++c)
        if (img.at(x, y, c) != -1.0f) return false;
    return true;
}

// True if `out` holds the stub value -1 at a texel where `in` (same size) does not; with
// `everywhere`, true if every texel of `out` holds it.
bool stubOutput(const Image& out, const Image* in, bool everywhere = false) {
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            const bool stub = isStubTexel(out, x, y);
            if (everywhere && !stub) return false;
            if (!everywhere && stub && !(in && isStubTexel(*in, x, y))) return true;
        }
    return everywhere;
}

}  // namespace

Renderer::Renderer(ShaderLibrary library) : library_(std::move(library)) {}
Renderer::~Renderer() = default;

std::vector<float> Renderer::gaussianWeights(int radius, float sigma) {
    if (radius <= 0) return {1.0f};
    const double s = sigma > 0.0f ? sigma : radius / 2.0;
    std::vector<double> w(radius + 1);
    double sum = 0.0;
    for (int k = 0; k <= radius; ++k) {
        w[k] = std::exp(-double(k) * k / (2.0 * s * s));
        sum += k == 0 ? w[k] : 2.0 * w[k];
    }
    std::vector<float> out(radius + 1);
    for (int k = 0; k <= radius; ++k) out[k] = float(w[k] / sum);
    return out;
}

GlProgram& Renderer::program(const std::string& first, const std::string& fragment,
                             const std::vector<std::string>& defines) {
    std::string key = first + "|" + fragment;
    for (const auto& d : defines) key += "|" + d;
    auto& slot = programs_[key];
    if (!slot) {
        slot = std::make_unique<GlProgram>(
            fragment.empty() ? GlProgram::compute(library_, first, defines)
                             : GlProgram::graphics(library_, first, fragment, defines));
    }
    return *slot;
}

GlProgram& Renderer::passProgram(PassKind kind, int blurRadius,
                                 const std::vector<std::string>& defines) {
    switch (kind) {
        case PassKind::Shadow: return program("scene.vert", "shadow_moments.frag", defines);
        case PassKind::GaussianX:
        case PassKind::GaussianY:
            // The radius is a compile-time constant (one program per radius): llvmpipe then
            // unrolls the taps and keeps the window in registers (docs/performance.md).
            return program("gaussian_blur.comp", "",
                           {"SL_BLUR_RADIUS=" + std::to_string(blurRadius)});
        case PassKind::SatRows:
        case PassKind::SatColumns: return program("sat.comp", "", {});
        case PassKind::SatResolve: return program("sat_resolve.comp", "", {});
        case PassKind::Lighting: return program("scene.vert", "lighting.frag", defines);
    }
    throw std::logic_error("no program for this pass");
}

void Renderer::dispatchLines(const GlProgram& p, glm::ivec2 size, glm::ivec2 direction,
                             bool wholeLine) {
    const glm::ivec3 local = p.workGroupSize();
    const int lineLength = direction.x == 1 ? size.x : size.y;
    const int lineCount = direction.x == 1 ? size.y : size.x;
    const int groupsX = wholeLine ? 1 : (lineLength + local.x - 1) / local.x;
    const int groupsY = (lineCount + local.y - 1) / local.y;
    gl::DispatchCompute(GLuint(groupsX), GLuint(groupsY), 1);
    gl::MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void Renderer::copyPass(const Texture& src, const Texture& dst) {
    GlProgram& p = program("copy.comp", "", {});
    p.use();
    p.set("uImageSize", glm::ivec2(src.width, src.height));
    gl::BindImageTexture(0, src.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    gl::BindImageTexture(1, dst.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatchLines(p, {src.width, src.height}, {1, 0}, false);
}

void Renderer::gaussianPass(const Texture& src, const Texture& dst, int radius, float sigma,
                            glm::ivec2 direction) {
    GlProgram& p = passProgram(PassKind::GaussianX, radius, {});
    BufferHandle& buffer = gaussianWeights_[{radius, sigma}];  // made once, not per pass
    if (!buffer) {
        std::vector<float> weights = gaussianWeights(radius, sigma);
        buffer = createBuffer(weights.data(), GLsizeiptr(weights.size() * sizeof(float)));
    }
    p.use();
    p.set("uRadius", radius);
    p.set("uDirection", direction);
    p.set("uImageSize", glm::ivec2(src.width, src.height));
    gl::BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer.id());
    gl::BindImageTexture(0, src.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    gl::BindImageTexture(1, dst.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    // Each invocation writes `texels` consecutive texels along the blur direction.
    const int texels = std::max(1, p.getInt("uTexelsPerInvocation", 1));
    const glm::ivec3 local = p.workGroupSize();
    const glm::ivec2 cover(local.x * (direction.x == 1 ? texels : 1),
                           local.y * (direction.y == 1 ? texels : 1));
    gl::DispatchCompute(GLuint((src.width + cover.x - 1) / cover.x),
                        GLuint((src.height + cover.y - 1) / cover.y), 1);
    gl::MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void Renderer::satPass(const Texture& src, const Texture& dst, glm::ivec2 direction) {
    GlProgram& p = passProgram(PassKind::SatRows, 0, {});
    p.use();
    p.set("uDirection", direction);
    p.set("uImageSize", glm::ivec2(src.width, src.height));
    gl::BindImageTexture(0, src.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    gl::BindImageTexture(1, dst.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatchLines(p, {src.width, src.height}, direction, true);
}

void Renderer::satResolvePass(const Texture& sat, const Texture& dst, float kernelTexels) {
    GlProgram& p = passProgram(PassKind::SatResolve, 0, {});
    p.use();
    p.set("uSat", 0);
    p.set("uSatKernel", kernelTexels);
    gl::BindTextureUnit(0, sat.id());
    gl::BindImageTexture(1, dst.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    const glm::ivec3 local = p.workGroupSize();
    gl::DispatchCompute(GLuint((sat.width + local.x - 1) / local.x),
                        GLuint((sat.height + local.y - 1) / local.y), 1);
    gl::MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

RenderResult Renderer::render(const Scene& scene, const PassPlan& plan,
                              const std::map<int, Image>* moments) {
    if (scene.lights.size() > 4) throw std::runtime_error(scene.path + ": at most 4 lights");
    RenderResult result;
    SceneGeometry geometry(scene);
    const ShadowEffect& fx = scene.shadow;
    const int n = fx.mapSize;

    std::vector<LightView> views;
    for (const Light& light : scene.lights)
        views.push_back(computeLightView(light, fx, geometry.bounds()));
    std::map<int, ShadowMaps> maps;
    for (int li : plan.shadowLights) {
        ShadowMaps& m = maps[li];
        m.view = views[li];
        const Image* given = moments && moments->count(li) ? &moments->at(li) : nullptr;
        m.raw = given ? Texture::create(given->width, given->height, GL_RGBA32F, GL_LINEAR)
                      : Texture::create(n, n, GL_RGBA32F, GL_LINEAR);
        if (given) m.raw.upload(*given);
        m.given = given != nullptr;
        m.depth = Texture::create(n, n, GL_DEPTH_COMPONENT32F);
        m.forLighting = &m.raw;
        if (fx.filter != FilterKind::None) {
            m.scratch = Texture::create(n, n, GL_RGBA32F);
            m.filtered = Texture::create(n, n, GL_RGBA32F, GL_LINEAR);
        }
        if (fx.filter == FilterKind::Sat) m.sat = Texture::create(n, n, GL_RGBA32F);
    }
    std::vector<std::string> defines = {"SL_TECHNIQUE_MSM4"};
    if (fx.filter == FilterKind::Sat) defines.push_back("SL_FILTER_SAT");

    struct CameraTargets { Texture color, shadow, depth; };
    std::map<int, CameraTargets> targets;

    // Compile first, so that pass times measure rendering, not the driver's compiler.
    for (const PlannedPass& pass : plan.passes) passProgram(pass.kind, fx.gaussianRadius, defines);

    gl::Enable(GL_DEPTH_TEST);
    gl::DepthFunc(GL_LESS);
    for (const PlannedPass& pass : plan.passes) {
        const auto start = std::chrono::steady_clock::now();
        ShadowMaps* m = pass.light >= 0 ? &maps.at(pass.light) : nullptr;
        if (m && m->given) {  // the caller's moments stand in for this light's passes
            result.passMillis.push_back(0.0);
            continue;
        }
        switch (pass.kind) {
            case PassKind::Shadow: {
                FramebufferHandle fb = makeFramebuffer({&m->raw}, m->depth);
                const float farMoments[4] = {1, 1, 1, 1};  // relative depth 1: nothing in front
                const float farDepth = 1.0f;
                gl::ClearNamedFramebufferfv(fb.id(), GL_COLOR, 0, farMoments);
                gl::ClearNamedFramebufferfv(fb.id(), GL_DEPTH, 0, &farDepth);
                gl::BindFramebuffer(GL_FRAMEBUFFER, fb.id());
                gl::Viewport(0, 0, n, n);
                GlProgram& p = passProgram(PassKind::Shadow, 0, defines);
                p.use();
                p.set("uViewProjection", m->view.viewProjection);
                p.set("uLightEye", m->view.eye);
                p.set("uLightForward", m->view.forward);
                p.set("uDepthRange", m->view.depthRange);
                geometry.draw(p, true, false);
                gl::BindFramebuffer(GL_FRAMEBUFFER, 0);
                break;
            }
            case PassKind::GaussianX:
                gaussianPass(m->raw, m->scratch, fx.gaussianRadius, fx.gaussianSigma, {1, 0});
                break;
            case PassKind::GaussianY:
                gaussianPass(m->scratch, m->filtered, fx.gaussianRadius, fx.gaussianSigma, {0, 1});
                m->forLighting = &m->filtered;
                break;
            case PassKind::SatRows: satPass(m->raw, m->scratch, {1, 0}); break;
            case PassKind::SatColumns:
                satPass(m->scratch, m->sat, {0, 1});
                m->forLighting = &m->sat;
                break;
            case PassKind::SatResolve: satResolvePass(m->sat, m->filtered, fx.satKernelTexels); break;
            case PassKind::Lighting: {
                const Camera& cam = scene.cameras.at(pass.camera);
                CameraTargets& t = targets[pass.camera];
                t.color = Texture::create(cam.width, cam.height, GL_RGBA32F);
                t.shadow = Texture::create(cam.width, cam.height, GL_R32F);
                t.depth = Texture::create(cam.width, cam.height, GL_DEPTH_COMPONENT32F);
                FramebufferHandle fb = makeFramebuffer({&t.color, &t.shadow}, t.depth);
                const float bg[4] = {scene.background.x, scene.background.y, scene.background.z, 1};
                const float zero[4] = {0, 0, 0, 0};
                const float farDepth = 1.0f;
                gl::ClearNamedFramebufferfv(fb.id(), GL_COLOR, 0, bg);
                gl::ClearNamedFramebufferfv(fb.id(), GL_COLOR, 1, zero);
                gl::ClearNamedFramebufferfv(fb.id(), GL_DEPTH, 0, &farDepth);
                gl::BindFramebuffer(GL_FRAMEBUFFER, fb.id());
                gl::Viewport(0, 0, cam.width, cam.height);
                GlProgram& p = passProgram(PassKind::Lighting, 0, defines);
                p.use();
                CameraView cv = computeCameraView(cam);
                p.set("uViewProjection", cv.viewProjection);
                p.set("uCameraPosition", cam.position);
                p.set("uAmbient", scene.ambient);
                p.set("uMomentBias", fx.momentBias);
                p.set("uDepthBias", fx.depthBias);
                p.set("uSatKernel", fx.satKernelTexels);
                std::vector<glm::vec3> eye, forward, color;
                std::vector<int> isSpot, mapIndex, units = {0, 1, 2, 3};
                std::vector<float> cosHalfCone;
                std::vector<glm::mat4> viewProj;
                std::vector<glm::vec2> range;
                int unit = 0;
                for (size_t i = 0; i < scene.lights.size(); ++i) {
                    const Light& l = scene.lights[i];
                    eye.push_back(views[i].eye);
                    forward.push_back(views[i].forward);
                    color.push_back(l.color * l.intensity);
                    isSpot.push_back(l.type == LightType::Spot);
                    cosHalfCone.push_back(std::cos(glm::radians(l.coneDegrees * 0.5f)));
                    viewProj.push_back(views[i].viewProjection);
                    range.push_back(views[i].depthRange);
                    auto it = maps.find(int(i));
                    if (it != maps.end()) {
                        gl::BindTextureUnit(GLuint(unit), it->second.forLighting->id());
                        mapIndex.push_back(unit++);
                    } else {
                        mapIndex.push_back(-1);
                    }
                }
                p.set("uLightCount", int(scene.lights.size()));
                p.setArray("uLightEye", eye);
                p.setArray("uLightForward", forward);
                p.setArray("uLightColor", color);
                p.setArray("uLightIsSpot", isSpot);
                p.setArray("uLightCosHalfCone", cosHalfCone);
                p.setArray("uLightShadowMap", mapIndex);
                p.setArray("uLightViewProjection", viewProj);
                p.setArray("uLightDepthRange", range);
                p.setArray("uShadowMaps", units);
                geometry.draw(p, false, true);
                gl::BindFramebuffer(GL_FRAMEBUFFER, 0);
                break;
            }
        }
        gl::Finish();
        result.passMillis.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
    }

    // Read back, and tell unimplemented stages apart from wrong ones by the stub value.
    auto note = [&](const std::string& file, const std::string& function) {
        std::string line = library_.displayPath(library_.resolve(file)) + ": " + function +
                           ": not implemented yet (its output is the stub value -1)";
        for (const auto& existing : result.stubNotes)
            if (existing == line) return;
        result.stubNotes.push_back(line);
    };
    for (const auto& [li, m] : maps) {
        const std::string suffix = li == plan.shadowLights.front() ? ""
                                                                   : "_light" + std::to_string(li);
        Image raw = m.raw.read();
        if (stubOutput(raw, nullptr)) note("moments.glsl", "computeMoments");
        if (fx.filter == FilterKind::Gaussian) {
            Image filtered = m.filtered.read();
            if (stubOutput(filtered, &raw)) note("gaussian_blur.comp", "gaussian blur pass");
            result.images["moments_filtered" + suffix] = std::move(filtered);
        } else if (fx.filter == FilterKind::Sat) {
            Image sat = m.sat.read();
            if (stubOutput(sat, &raw)) note("sat.comp", "prefix-sum pass");
            if (plan.passes.end() != std::find_if(plan.passes.begin(), plan.passes.end(),
                                                  [](const PlannedPass& p) {
                                                      return p.kind == PassKind::SatResolve;
                                                  })) {
                Image filtered = m.filtered.read();
                // A stub table makes a correct lookup return ~0, never -1 everywhere.
                if (stubOutput(filtered, &sat) || stubOutput(filtered, nullptr, true))
                    note("sat_lookup.glsl", "satBoxAverage");
                result.images["moments_filtered" + suffix] = std::move(filtered);
            }
            result.images["sat" + suffix] = std::move(sat);
        } else {
            result.images["moments_filtered" + suffix] = raw;
        }
        result.images["moments_raw" + suffix] = std::move(raw);
    }
    for (const auto& [ci, t] : targets) {
        const std::string suffix = ci == 0 ? "" : "_" + scene.cameras[ci].name;
        Image shadow = t.shadow.read();
        if (!maps.empty() && stubOutput(shadow, nullptr)) note("msm.glsl", "momentShadowIntensity");
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
