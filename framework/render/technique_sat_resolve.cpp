// Renderer::techniqueSatResolvePass: the framework techniques' SAT resolve (a filter pass of
// the framework's own, outside filter_passes.cpp): the double-float table (hi, lo) back into a
// filtered map, with the lighting's own boxAverage (techniques/sat_resolve.comp).
#include "renderer.h"

namespace sl {

void Renderer::techniqueSatResolvePass(const Texture& hi, const Texture& lo, const Texture& dst,
                                       float kernelTexels) {
    GlProgram& p = techniqueProgram(PassKind::SatResolve, false, dst.format, 0, {});
    p.use();
    p.setArray("uShadowMaps", std::vector<int>{0, 1});
    p.set("uMapTexels", glm::vec2(float(dst.width), float(dst.height)));
    p.set("uSatKernel", kernelTexels);
    gl::BindTextureUnit(0, hi.id());
    gl::BindTextureUnit(1, lo.id());
    gl::BindImageTexture(0, dst.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, dst.format);
    const glm::ivec3 local = p.workGroupSize();
    gl::DispatchCompute(GLuint((dst.width + local.x - 1) / local.x),
                        GLuint((dst.height + local.y - 1) / local.y), 1);
    gl::MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace sl
