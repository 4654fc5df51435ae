// probe: one dispatch of shaders/probe_*.comp over SSBOs (see probe.h).
#include "probe.h"

#include "gl_program.h"
#include "gpu_resources.h"
#include "renderer.h"

#include <algorithm>
#include <stdexcept>

namespace sl {
namespace {

template <typename Out>
std::vector<Out> runProbe(const GlProgram& program, size_t count) {
    std::vector<Out> results(count);
    BufferHandle out = createBuffer(nullptr, GLsizeiptr(std::max<size_t>(count, 1) * sizeof(Out)));
    gl::BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, out.id());
    program.use();
    program.set("uCount", int(count));
    gl::DispatchCompute(GLuint((count + 63) / 64), 1, 1);
    gl::MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    if (count) gl::GetNamedBufferSubData(out.id(), 0, GLsizeiptr(count * sizeof(Out)), results.data());
    return results;
}

}  // namespace

std::vector<float> probeMomentShadowIntensity(const ShaderLibrary& library,
                                              const std::vector<glm::vec4>& b,
                                              const std::vector<float>& zf, float momentBias) {
    if (b.size() != zf.size()) throw std::invalid_argument("probe: b and zf differ in length");
    GlProgram program = GlProgram::compute(library, "probe_msm.comp", {"SL_TECHNIQUE_MSM4"});
    program.set("uMomentBias", momentBias);
    BufferHandle bBuf = createBuffer(b.data(), GLsizeiptr(std::max<size_t>(b.size(), 1) * 16));
    BufferHandle zBuf = createBuffer(zf.data(), GLsizeiptr(std::max<size_t>(zf.size(), 1) * 4));
    gl::BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, bBuf.id());
    gl::BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, zBuf.id());
    return runProbe<float>(program, b.size());
}

static std::vector<glm::vec4> runMomentsProbe(const ShaderLibrary& library,
                                              const std::vector<glm::vec3>& inputs, bool depthAlone) {
    GlProgram program = GlProgram::compute(library, "probe_moments.comp", {});
    std::vector<glm::vec4> padded;
    for (const auto& v : inputs) padded.emplace_back(v, depthAlone ? 1.0f : 0.0f);
    BufferHandle in = createBuffer(padded.data(),
                                   GLsizeiptr(std::max<size_t>(padded.size(), 1) * 16));
    gl::BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    return runProbe<glm::vec4>(program, inputs.size());
}

std::vector<glm::vec4> probeMoments(const ShaderLibrary& library,
                                    const std::vector<glm::vec3>& inputs) {
    return runMomentsProbe(library, inputs, false);
}

std::vector<float> probeRelativeDepth(const ShaderLibrary& library,
                                      const std::vector<glm::vec3>& inputs) {
    std::vector<float> z;
    for (const glm::vec4& v : runMomentsProbe(library, inputs, true)) z.push_back(v.x);
    return z;
}

// The solution's table of `moments`, built by its sat.comp with the renderer's dispatches.
static Texture probeSatTable(const ShaderLibrary& library, const Image& moments) {
    if (moments.channels != 4 || moments.empty())
        throw std::invalid_argument("probe: the SAT probe needs a non-empty RGBA moment map");
    Renderer renderer(library);  // its satPass: the same dispatch as a render
    Texture src = Texture::create(moments.width, moments.height, GL_RGBA32F);
    const int tableWidth = satTableWidth(moments.width);
    Texture rows = Texture::create(tableWidth, moments.height, GL_RGBA32F);
    Texture table = Texture::create(tableWidth, moments.height, GL_RGBA32F);
    src.upload(moments);
    renderer.satPass(src, rows, {1, 0});
    renderer.satPass(rows, table, {0, 1});
    gl::MemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    return table;
}

Image probeSatTableImage(const ShaderLibrary& library, const Image& moments) {
    Texture table = probeSatTable(library, moments);
    gl::MemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    return table.read();
}

std::vector<float> probeSatKernelTexels(const ShaderLibrary& library, const Image& moments,
                                        const std::vector<SatKernelCase>& cases) {
    Texture table = probeSatTable(library, moments);
    GlProgram program = GlProgram::compute(library, "probe_sat_kernel.comp", {"SL_FILTER_SAT"});
    program.use();
    program.set("uSat", 0);
    gl::BindTextureUnit(0, table.id());
    std::vector<glm::vec4> packed;
    for (const SatKernelCase& c : cases) {
        packed.emplace_back(c.center, c.searchTexels, c.zr);
        packed.emplace_back(c.depthRange, c.lightTexels, c.perspective ? 1.0f : 0.0f);
        packed.emplace_back(c.kernelRange, 0.0f, 0.0f);
    }
    BufferHandle in = createBuffer(packed.data(), GLsizeiptr(std::max<size_t>(packed.size(), 1) * 16));
    gl::BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    return runProbe<float>(program, cases.size());
}

std::vector<glm::vec4> probeSatBoxAverage(const ShaderLibrary& library, const Image& moments,
                                          const std::vector<glm::vec4>& boxes) {
    Texture table = probeSatTable(library, moments);
    GlProgram program = GlProgram::compute(library, "probe_sat_lookup.comp", {"SL_FILTER_SAT"});
    program.use();
    program.set("uSat", 0);
    gl::BindTextureUnit(0, table.id());
    BufferHandle in = createBuffer(boxes.data(), GLsizeiptr(std::max<size_t>(boxes.size(), 1) * 16));
    gl::BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    return runProbe<glm::vec4>(program, boxes.size());
}

Image probeGaussianBlur(const ShaderLibrary& library, const Image& map, int radius, float sigma,
                        bool alongX, bool alongY) {
    if (map.channels != 4 || map.empty())
        throw std::invalid_argument("probe: the Gaussian probe needs a non-empty RGBA map");
    Renderer renderer(library);  // its gaussianPass: the same dispatch as a render
    Texture a = Texture::create(map.width, map.height, GL_RGBA32F);
    Texture b = Texture::create(map.width, map.height, GL_RGBA32F);
    a.upload(map);
    const Texture* result = &a;
    if (alongX) renderer.gaussianPass(a, b, radius, sigma, {1, 0}), result = &b;
    if (alongY) {
        const Texture& dst = result == &a ? b : a;
        renderer.gaussianPass(*result, dst, radius, sigma, {0, 1});
        result = &dst;
    }
    gl::MemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    return result->read();
}

}  // namespace sl
