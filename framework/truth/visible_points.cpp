// visible_points: the camera's visible points from the rasteriser (see visible_points.h).
#include "visible_points.h"

#include "gl_program.h"
#include "gpu_resources.h"
#include "light_view.h"
#include "scene_geometry.h"

#include <stdexcept>

namespace sl {

VisiblePoints renderVisiblePoints(const Scene& scene, const ShaderLibrary& library,
                                  int cameraIndex) {
    const Camera& cam = scene.cameras.at(size_t(cameraIndex));
    SceneGeometry geometry(scene);
    GlProgram program = GlProgram::graphics(library, "scene.vert", "world_position.frag", {});
    Texture targets[3] = {Texture::create(cam.width, cam.height, GL_RGBA32F),
                          Texture::create(cam.width, cam.height, GL_RGBA32F),
                          Texture::create(cam.width, cam.height, GL_RGBA32F)};
    Texture depth = Texture::create(cam.width, cam.height, GL_DEPTH_COMPONENT32F);
    GLuint id = 0;
    gl::CreateFramebuffers(1, &id);
    FramebufferHandle fb(id);
    const GLenum buffers[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    for (int i = 0; i < 3; ++i) gl::NamedFramebufferTexture(id, buffers[i], targets[i].id(), 0);
    gl::NamedFramebufferTexture(id, GL_DEPTH_ATTACHMENT, depth.id(), 0);
    gl::NamedFramebufferDrawBuffers(id, 3, buffers);
    if (gl::CheckNamedFramebufferStatus(id, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("renderVisiblePoints: framebuffer incomplete");
    const float zero[4] = {0, 0, 0, 0};
    const float farDepth = 1.0f;
    for (int i = 0; i < 3; ++i) gl::ClearNamedFramebufferfv(id, GL_COLOR, i, zero);
    gl::ClearNamedFramebufferfv(id, GL_DEPTH, 0, &farDepth);
    gl::BindFramebuffer(GL_FRAMEBUFFER, id);
    gl::Viewport(0, 0, cam.width, cam.height);
    gl::Enable(GL_DEPTH_TEST);  // as the lighting pass: GL_LESS against a cleared 1.0
    gl::DepthFunc(GL_LESS);
    program.use();
    program.set("uViewProjection", computeCameraView(cam).viewProjection);
    geometry.draw(program, false, false);
    gl::BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::Finish();
    VisiblePoints v;
    v.width = cam.width;
    v.height = cam.height;
    v.position = targets[0].read();
    v.shadingNormal = targets[1].read();
    v.geometricNormal = targets[2].read();
    return v;
}

}  // namespace sl
