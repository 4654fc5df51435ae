// Renderer's filter passes: copy, widen, the solution's separable Gaussian and summed-area table
// (RGBA32F, one layer per dispatch) and the SAT resolve. One dispatch each; the benchmark and
// the grader call them directly.
#include "render_internal.h"
#include "renderer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sl {

using render_detail::dispatchTexelRuns;


namespace render_detail {

void dispatchTexelRuns(const GlProgram& p, glm::ivec2 size, glm::ivec2 direction) {
    const int texels = std::max(1, p.getInt("uTexelsPerInvocation", 1));  // 1 unless declared
    const glm::ivec3 local = p.workGroupSize();
    const glm::ivec2 cover(local.x * (direction.x == 1 ? texels : 1),
                           local.y * (direction.y == 1 ? texels : 1));
    gl::DispatchCompute(GLuint((size.x + cover.x - 1) / cover.x),
                        GLuint((size.y + cover.y - 1) / cover.y), 1);
    gl::MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace render_detail

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
    gaussianPass(passProgram(PassKind::GaussianX, radius, {}), src, dst, radius, sigma, direction);
}

void Renderer::gaussianPass(GlProgram& p, const Texture& src, const Texture& dst, int radius,
                            float sigma, glm::ivec2 direction) {
    const BufferHandle& buffer = weightsBuffer(radius, sigma);
    p.use();
    p.set("uRadius", radius);
    p.set("uDirection", direction);
    p.set("uImageSize", glm::ivec2(src.width, src.height));
    gl::BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer.id());
    gl::BindImageTexture(0, src.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    gl::BindImageTexture(1, dst.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatchTexelRuns(p, {src.width, src.height}, direction);
}

const BufferHandle& Renderer::weightsBuffer(int radius, float sigma) {
    BufferHandle& buffer = gaussianWeights_[{radius, sigma}];  // made once, not per pass
    if (!buffer) {
        std::vector<float> weights = gaussianWeights(radius, sigma);
        buffer = createBuffer(weights.data(), GLsizeiptr(weights.size() * sizeof(float)));
    }
    return buffer;
}

void Renderer::widenPass(const Texture& src, const Texture& dst) {
    widenPass(passProgram(PassKind::Widen, 0, {}), src, dst);
}

void Renderer::widenPass(GlProgram& p, const Texture& src, const Texture& dst) {
    p.use();
    p.set("uSource", 0);
    gl::BindTextureUnit(0, src.id());
    gl::BindImageTexture(1, dst.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatchLines(p, {src.width, src.height}, {1, 0}, false);
}

void Renderer::satPass(const Texture& src, const Texture& dst, glm::ivec2 direction) {
    satPass(passProgram(PassKind::SatRows, 0, {}), src, dst, direction);
}

void Renderer::satPass(GlProgram& p, const Texture& src, const Texture& dst, glm::ivec2 direction) {
    p.use();
    p.set("uDirection", direction);
    const glm::ivec2 map(dst.width / satTableWidth(1), dst.height);  // the moment map's size
    p.set("uImageSize", map);
    gl::BindImageTexture(0, src.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    gl::BindImageTexture(1, dst.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatchLines(p, map, direction, true);
}

void Renderer::satResolvePass(const Texture& sat, const Texture& dst, float kernelTexels) {
    satResolvePass(passProgram(PassKind::SatResolve, 0, {}), sat, dst, kernelTexels);
}

void Renderer::satResolvePass(GlProgram& p, const Texture& sat, const Texture& dst,
                              float kernelTexels) {
    p.use();
    p.set("uSat", 0);
    p.set("uSatKernel", kernelTexels);
    gl::BindTextureUnit(0, sat.id());
    gl::BindImageTexture(1, dst.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    const glm::ivec3 local = p.workGroupSize();
    gl::DispatchCompute(GLuint((dst.width + local.x - 1) / local.x),
                        GLuint((dst.height + local.y - 1) / local.y), 1);
    gl::MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace sl
