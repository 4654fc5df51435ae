// Renderer: executes the planned passes (see renderer.h).
#include "renderer.h"

#include "light_view.h"
#include "scene_geometry.h"
#include "technique.h"

#include <algorithm>
#include <cctype>
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

// The textures of one shadowing light, by role (pass_plan.h), each a list of layers.
struct ShadowMaps {
    std::map<std::string, std::vector<Texture>> tex;
    bool given = false;  // raw came from the caller: no shadow or filter pass runs
    LightView view;
    std::vector<const Texture*> forLighting;  // what lighting samples, in unit order
    Texture& one(const std::string& role) { return tex.at(role).front(); }
};

// GLSL image format qualifier of a texture format.
std::string imageFormat(GLenum format) {
    switch (format) {
        case GL_R32F: return "r32f";
        case GL_RG32F: return "rg32f";
        case GL_RGBA32F: return "rgba32f";
        case GL_RGBA16: return "rgba16";
    }
    throw std::logic_error("no image format for texture format " + std::to_string(format));
}

// Sampled maps filter bilinearly (filtering depth or moments is linear); tables do not.
GLenum samplerFilter(const std::string& role) {
    return role == "raw" || role == "filtered" || role == "second" ? GL_LINEAR : GL_NEAREST;
}

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

void noteStub(const ShaderLibrary& library, RenderResult& result, const std::string& file,
              const std::string& function) {
    std::string line = library.displayPath(library.resolve(file)) + ": " + function +
                       ": not implemented yet (its output is the stub value -1)";
    for (const auto& existing : result.stubNotes)
        if (existing == line) return;
    result.stubNotes.push_back(line);
}

// A technique's parameters as the uniforms u<Name> (the shadow pass's warps, the lighting's).
void setTechniqueParameters(const GlProgram& p, const ShadowEffect& fx) {
    for (const auto& [name, value] : resolvedParameters(fx)) {
        const std::string uniform = "u" + std::string(1, char(std::toupper(name[0]))) + name.substr(1);
        p.set(uniform.c_str(), float(value));
    }
}

// The uniforms of a framework technique's lighting permutation: its parameters as u<Name>,
// the sampler units, the map size and the Gaussian weights (PCF uses the moment filter's).
void setTechniqueUniforms(const GlProgram& p, const ShadowEffect& fx, int unitsUsed) {
    constexpr int kMaxMaps = 16;  // SL_MAX_MAPS in shaders/techniques/common.glsl
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

// Reads the maps back into `result`, and tells unimplemented stages apart from wrong ones by
// the stub value (student stages only).
void readBack(const ShaderLibrary& library, const TechniqueRow& row, const ShadowEffect& fx,
              const PassPlan& plan, std::map<int, ShadowMaps>& maps, RenderResult& result) {
    for (auto& [li, m] : maps) {
        const std::string suffix = li == plan.shadowLights.front() ? ""
                                                                   : "_light" + std::to_string(li);
        const auto& rawLayers = m.tex.at("raw");
        Image raw = rawLayers.front().read();
        if (!row.studentStages) {
            for (size_t k = 1; k < rawLayers.size(); ++k)
                result.images["moments_raw" + suffix + "_layer" + std::to_string(k)] =
                    rawLayers[k].read();
            if (m.tex.count("second")) result.images["second_depth" + suffix] = m.one("second").read();
            if (m.tex.count("filtered"))
                result.images["moments_filtered" + suffix] = m.one("filtered").read();
            else if (!m.tex.count("sat-hi"))
                result.images["moments_filtered" + suffix] = raw;
            result.images["moments_raw" + suffix] = std::move(raw);
            continue;
        }
        if (stubOutput(raw, nullptr)) noteStub(library, result, "moments.glsl", "computeMoments");
        if (fx.filter == FilterKind::Gaussian) {
            Image filtered = m.one("filtered").read();
            if (stubOutput(filtered, &raw))
                noteStub(library, result, "gaussian_blur.comp", "gaussian blur pass");
            result.images["moments_filtered" + suffix] = std::move(filtered);
        } else if (fx.filter == FilterKind::Sat) {
            Image sat = m.one("sat").read();
            if (stubOutput(sat, &raw)) noteStub(library, result, "sat.comp", "prefix-sum pass");
            if (plan.passes.end() != std::find_if(plan.passes.begin(), plan.passes.end(),
                                                  [](const PlannedPass& p) {
                                                      return p.kind == PassKind::SatResolve;
                                                  })) {
                Image filtered = m.one("filtered").read();
                // A stub table makes a correct lookup return ~0, never -1 everywhere.
                if (stubOutput(filtered, &sat) || stubOutput(filtered, nullptr, true))
                    noteStub(library, result, "sat_lookup.glsl", "satBoxAverage");
                result.images["moments_filtered" + suffix] = std::move(filtered);
            }
            result.images["sat" + suffix] = std::move(sat);
        } else {
            result.images["moments_filtered" + suffix] = raw;
        }
        result.images["moments_raw" + suffix] = std::move(raw);
    }
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
        case PassKind::ShadowSecond: break;  // framework techniques only (techniqueProgram)
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
    const BufferHandle& buffer = weightsBuffer(radius, sigma);
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

const BufferHandle& Renderer::weightsBuffer(int radius, float sigma) {
    BufferHandle& buffer = gaussianWeights_[{radius, sigma}];  // made once, not per pass
    if (!buffer) {
        std::vector<float> weights = gaussianWeights(radius, sigma);
        buffer = createBuffer(weights.data(), GLsizeiptr(weights.size() * sizeof(float)));
    }
    return buffer;
}

GlProgram& Renderer::techniqueProgram(PassKind kind, bool studentStages, unsigned mapFormat,
                                      const std::vector<std::string>& defines) {
    if (studentStages || kind == PassKind::Lighting) return passProgram(kind, 0, defines);
    const std::string format = "SL_MAP_FORMAT=" + imageFormat(mapFormat);
    switch (kind) {
        case PassKind::Shadow: return program("scene.vert", "techniques/store.frag", defines);
        case PassKind::ShadowSecond:
            return program("scene.vert", "techniques/second_depth_peel.frag", defines);
        case PassKind::GaussianX:
        case PassKind::GaussianY: return program("techniques/filter_gaussian.comp", "", {format});
        case PassKind::SatRows:
        case PassKind::SatColumns: {
            // The table's own format: float32 with the map's channel count.
            const GLenum sat = mapFormat == GL_RGBA16 ? GL_RGBA32F : GLenum(mapFormat);
            std::vector<std::string> d = {format, "SL_SAT_FORMAT=" + imageFormat(sat)};
            if (kind == PassKind::SatColumns) d.push_back("SL_SAT_COLUMNS");
            return program("techniques/filter_sat.comp", "", d);
        }
        default: break;
    }
    throw std::logic_error(std::string("no framework program for pass ") + toString(kind));
}

void Renderer::techniqueGaussianPass(const Texture& src, const Texture& dst, int radius,
                                     float sigma, glm::ivec2 direction) {
    GlProgram& p = techniqueProgram(PassKind::GaussianX, false, src.format, {});
    p.use();
    p.set("uRadius", radius);
    p.set("uDirection", direction);
    p.set("uImageSize", glm::ivec2(src.width, src.height));
    gl::BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, weightsBuffer(radius, sigma).id());
    gl::BindImageTexture(0, src.id(), 0, GL_FALSE, 0, GL_READ_ONLY, src.format);
    gl::BindImageTexture(1, dst.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, dst.format);
    const glm::ivec3 local = p.workGroupSize();
    gl::DispatchCompute(GLuint((src.width + local.x - 1) / local.x),
                        GLuint((src.height + local.y - 1) / local.y), 1);
    gl::MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void Renderer::techniqueSatPass(const Texture& src, const Texture& hi, const Texture& lo,
                                glm::ivec2 direction) {
    const bool rows = direction.x == 1;
    GlProgram& p = techniqueProgram(rows ? PassKind::SatRows : PassKind::SatColumns, false,
                                    src.format, {});
    p.use();
    p.set("uImageSize", glm::ivec2(hi.width, hi.height));
    if (rows) gl::BindImageTexture(0, src.id(), 0, GL_FALSE, 0, GL_READ_ONLY, src.format);
    gl::BindImageTexture(1, hi.id(), 0, GL_FALSE, 0, GL_READ_WRITE, hi.format);
    gl::BindImageTexture(2, lo.id(), 0, GL_FALSE, 0, GL_READ_WRITE, lo.format);
    dispatchLines(p, {hi.width, hi.height}, direction, true);
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
    const TechniqueRow& row = techniqueRow(fx.technique);
    const int n = fx.mapSize;
    const std::vector<std::string>& defines = plan.defines;

    std::vector<LightView> views;
    for (const Light& light : scene.lights)
        views.push_back(computeLightView(light, fx, geometry.bounds()));
    // Allocate what the plan lists, and nothing else.
    std::map<int, ShadowMaps> maps;
    for (int li : plan.shadowLights) maps[li].view = views[li];
    for (const PlannedTexture& t : plan.textures) {
        if (t.light < 0) continue;
        ShadowMaps& m = maps[t.light];
        const Image* given = moments && moments->count(t.light) ? &moments->at(t.light) : nullptr;
        auto& layers = m.tex[t.role];
        if (t.role == "raw" && given) {
            layers.push_back(Texture::create(given->width, given->height, GL_RGBA32F, GL_LINEAR));
            layers.back().upload(*given);
            m.given = true;
            continue;
        }
        for (int k = 0; k < t.layers; ++k)
            layers.push_back(Texture::create(t.width, t.height, t.glFormat, samplerFilter(t.role)));
    }
    for (auto& [li, m] : maps)
        for (auto& t : m.tex.at("raw")) m.forLighting.push_back(&t);
    const MapLayout layout = mapLayout(fx);
    const std::vector<glm::vec4> clear = shadowClearValues(fx);

    struct CameraTargets { Texture color, shadow, depth; };
    std::map<int, CameraTargets> targets;

    // Compile first, so that pass times measure rendering, not the driver's compiler.
    for (const PlannedPass& pass : plan.passes) {
        if (row.studentStages) passProgram(pass.kind, fx.gaussianRadius, defines);
        else techniqueProgram(pass.kind, false, layout.glFormat, defines);
    }

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
            case PassKind::Shadow:
            case PassKind::ShadowSecond: {
                const bool second = pass.kind == PassKind::ShadowSecond;
                std::vector<const Texture*> colors;
                if (second) colors.push_back(&m->one("second"));
                else for (const Texture& t : m->tex.at("raw")) colors.push_back(&t);
                FramebufferHandle fb = makeFramebuffer(colors, m->one("depth"));
                const float farDepth = 1.0f;
                for (size_t k = 0; k < colors.size(); ++k) {
                    // Relative depth 1 everywhere: nothing in front (msm4: moments (1, 1, 1, 1)).
                    const glm::vec4 c = second ? glm::vec4(1.0f) : clear[k];
                    gl::ClearNamedFramebufferfv(fb.id(), GL_COLOR, GLint(k), &c.x);
                }
                gl::ClearNamedFramebufferfv(fb.id(), GL_DEPTH, 0, &farDepth);
                gl::BindFramebuffer(GL_FRAMEBUFFER, fb.id());
                gl::Viewport(0, 0, n, n);
                GlProgram& p = row.studentStages
                                   ? passProgram(PassKind::Shadow, 0, defines)
                                   : techniqueProgram(pass.kind, false, layout.glFormat, defines);
                p.use();
                p.set("uViewProjection", m->view.viewProjection);
                p.set("uLightEye", m->view.eye);
                p.set("uLightForward", m->view.forward);
                p.set("uDepthRange", m->view.depthRange);
                if (!row.studentStages) setTechniqueParameters(p, fx);
                if (second) {
                    const auto eps = float(techniqueParameter(fx, "peelEpsilon"));
                    p.set("uPeelEpsilon", eps);
                    p.set("uFirstDepth", 0);
                    gl::BindTextureUnit(0, m->one("raw").id());
                    m->forLighting.push_back(&m->one("second"));
                }
                geometry.draw(p, true, false);
                gl::BindFramebuffer(GL_FRAMEBUFFER, 0);
                break;
            }
            case PassKind::GaussianX:
            case PassKind::GaussianY: {
                const bool x = pass.kind == PassKind::GaussianX;
                auto& src = m->tex.at(x ? "raw" : "scratch");
                auto& dst = m->tex.at(x ? "scratch" : "filtered");
                for (size_t k = 0; k < src.size(); ++k) {
                    if (row.studentStages)
                        gaussianPass(src[k], dst[k], fx.gaussianRadius, fx.gaussianSigma,
                                     x ? glm::ivec2(1, 0) : glm::ivec2(0, 1));
                    else
                        techniqueGaussianPass(src[k], dst[k], fx.gaussianRadius, fx.gaussianSigma,
                                              x ? glm::ivec2(1, 0) : glm::ivec2(0, 1));
                }
                if (!x) {
                    m->forLighting.clear();
                    for (auto& t : dst) m->forLighting.push_back(&t);
                }
                break;
            }
            case PassKind::SatRows:
            case PassKind::SatColumns: {
                const glm::ivec2 dir = pass.kind == PassKind::SatRows ? glm::ivec2(1, 0)
                                                                      : glm::ivec2(0, 1);
                if (row.studentStages) {
                    if (pass.kind == PassKind::SatRows) {
                        satPass(m->one("raw"), m->one("scratch"), dir);
                    } else {
                        satPass(m->one("scratch"), m->one("sat"), dir);
                        m->forLighting = {&m->one("sat")};
                    }
                    break;
                }
                auto& raw = m->tex.at("raw");
                auto& hi = m->tex.at("sat-hi");
                auto& lo = m->tex.at("sat-lo");
                m->forLighting.clear();
                for (size_t k = 0; k < raw.size(); ++k) {
                    techniqueSatPass(raw[k], hi[k], lo[k], dir);
                    m->forLighting.push_back(&hi[k]);
                    m->forLighting.push_back(&lo[k]);
                }
                break;
            }
            case PassKind::SatResolve:
                satResolvePass(m->one("sat"), m->one("filtered"), fx.satKernelTexels);
                break;
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
                std::vector<float> cosHalfCone, lightSize, frustumScale;
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
                    lightSize.push_back(l.size);
                    // Width of the shadow frustum: spot: × the depth; directional: as is.
                    frustumScale.push_back(l.type == LightType::Spot
                                               ? 2.0f * std::tan(glm::radians(l.coneDegrees * 0.5f))
                                               : 2.0f * l.extent);
                    auto it = maps.find(int(i));
                    if (it != maps.end()) {
                        mapIndex.push_back(unit);
                        for (const Texture* tex : it->second.forLighting)
                            gl::BindTextureUnit(GLuint(unit++), tex->id());
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
                if (row.studentStages) {
                    p.setArray("uShadowMaps", units);
                } else {
                    setTechniqueUniforms(p, fx, unit);
                    p.setArray("uLightSize", lightSize);
                    p.setArray("uLightFrustumScale", frustumScale);
                }
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
    readBack(library_, row, fx, plan, maps, result);
    for (const auto& [ci, t] : targets) {
        const std::string suffix = ci == 0 ? "" : "_" + scene.cameras[ci].name;
        Image shadow = t.shadow.read();
        if (row.studentStages && !maps.empty() && stubOutput(shadow, nullptr))
            noteStub(library_, result, "msm.glsl", "momentShadowIntensity");
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
