// gpu_resources: texture creation and read-back (see gpu_resources.h).
#include "gpu_resources.h"

#include <stdexcept>
#include <string>

namespace sl {
namespace {

int channelsOf(GLenum format) {
    switch (format) {
        case GL_RGBA32F: return 4;
        case GL_RGBA16: return 4;  // UNORM16 (msm4-16bit), read back as floats in [0, 1]
        case GL_RG32F: return 2;
        case GL_R32F: return 1;
        case GL_DEPTH_COMPONENT32F: return 1;
    }
    throw std::logic_error("texture format without a read-back rule: " + std::to_string(format));
}

GLenum pixelFormatOf(GLenum format) {
    switch (format) {
        case GL_RGBA32F: return GL_RGBA;
        case GL_RGBA16: return GL_RGBA;
        case GL_RG32F: return GL_RG;
        case GL_R32F: return GL_RED;
        case GL_DEPTH_COMPONENT32F: return GL_DEPTH_COMPONENT;
    }
    throw std::logic_error("texture format without a pixel format: " + std::to_string(format));
}

}  // namespace

Texture Texture::create(int width, int height, GLenum format, GLenum filter) {
    Texture t;
    GLuint id = 0;
    gl::CreateTextures(GL_TEXTURE_2D, 1, &id);
    t.handle = GlHandle<deleteTexture>(id);
    t.width = width;
    t.height = height;
    t.format = format;
    gl::TextureStorage2D(id, 1, format, width, height);
    gl::TextureParameteri(id, GL_TEXTURE_MIN_FILTER, GLint(filter));
    gl::TextureParameteri(id, GL_TEXTURE_MAG_FILTER, GLint(filter));
    gl::TextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl::TextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

Image Texture::read() const {
    Image img(width, height, channelsOf(format));
    gl::PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl::GetTextureImage(id(), 0, pixelFormatOf(format), GL_FLOAT,
                        GLsizei(img.pixels.size() * sizeof(float)), img.pixels.data());
    return img;
}

void Texture::upload(const Image& image) {
    if (image.width != width || image.height != height || image.channels != channelsOf(format))
        throw std::invalid_argument("Texture::upload: image size or channels do not match");
    gl::PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl::TextureSubImage2D(id(), 0, 0, 0, width, height, pixelFormatOf(format), GL_FLOAT,
                          image.pixels.data());
}

BufferHandle createBuffer(const void* data, GLsizeiptr bytes) {
    GLuint id = 0;
    gl::CreateBuffers(1, &id);
    gl::NamedBufferStorage(id, bytes, data, 0);
    return BufferHandle(id);
}

}  // namespace sl
