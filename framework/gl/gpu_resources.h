// gpu_resources: owning handles for GL textures, framebuffers, buffers and vertex arrays, and
// texture read-back into an Image. Move-only; deleting a handle deletes the GL object.
#pragma once

#include "gl_api.h"
#include "image.h"

#include <utility>

namespace sl {

template <void (*Delete)(GLuint)>
class GlHandle {
public:
    GlHandle() = default;
    explicit GlHandle(GLuint id) : id_(id) {}
    GlHandle(const GlHandle&) = delete;
    GlHandle& operator=(const GlHandle&) = delete;
    GlHandle(GlHandle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
    GlHandle& operator=(GlHandle&& o) noexcept {
        if (this != &o) { reset(); id_ = std::exchange(o.id_, 0); }
        return *this;
    }
    ~GlHandle() { reset(); }
    void reset() { if (id_) Delete(std::exchange(id_, 0)); }
    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }

private:
    GLuint id_ = 0;
};

inline void deleteTexture(GLuint id) { gl::DeleteTextures(1, &id); }
inline void deleteFramebuffer(GLuint id) { gl::DeleteFramebuffers(1, &id); }
inline void deleteBuffer(GLuint id) { gl::DeleteBuffers(1, &id); }
inline void deleteVertexArray(GLuint id) { gl::DeleteVertexArrays(1, &id); }

using FramebufferHandle = GlHandle<deleteFramebuffer>;
using BufferHandle = GlHandle<deleteBuffer>;
using VertexArrayHandle = GlHandle<deleteVertexArray>;

// A 2D texture with one level. `format`: GL_RGBA32F, GL_R32F, GL_DEPTH_COMPONENT32F, ...
struct Texture {
    GlHandle<deleteTexture> handle;
    int width = 0, height = 0;
    GLenum format = 0;

    static Texture create(int width, int height, GLenum format, GLenum filter = GL_NEAREST);
    GLuint id() const { return handle.id(); }
    Image read() const;                 // channels from the format (RGBA32F: 4, R32F: 1)
    void upload(const Image& image);    // image size and channels must match
};

// A buffer filled once with `bytes` of `data`.
BufferHandle createBuffer(const void* data, GLsizeiptr bytes);

}  // namespace sl
