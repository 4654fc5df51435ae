// gl_api: the OpenGL 4.5 core functions Shadowlab calls, as function pointers in namespace
// `gl`, resolved through the active context's get-proc-address (OSMesa, EGL or GLFW).
//
// Why not link libGL: libOSMesa and libGL/libEGL export the same gl* symbols, so one binary
// that links both calls whichever the dynamic linker found first. Resolving every entry point
// through the backend that owns the current context avoids that, and lets one binary run all
// backends. (libepoxy and glbinding 2 resolve through GLX/EGL only, so they cannot serve OSMesa.)
#pragma once

#include <GL/glcorearb.h>

#include <string>

// X-macro: (return type, name without the gl prefix, parameter list).
#define SL_GL_FUNCTIONS(X)                                                                   \
    X(const GLubyte*, GetString, (GLenum name))                                              \
    X(void, GetIntegerv, (GLenum pname, GLint* data))                                        \
    X(GLenum, GetError, ())                                                                  \
    X(void, Enable, (GLenum cap))                                                            \
    X(void, Disable, (GLenum cap))                                                           \
    X(void, Viewport, (GLint x, GLint y, GLsizei w, GLsizei h))                              \
    X(void, DepthFunc, (GLenum func))                                                        \
    X(void, Finish, ())                                                                      \
    X(void, PixelStorei, (GLenum pname, GLint param))                                        \
    X(GLuint, CreateShader, (GLenum type))                                                   \
    X(void, ShaderSource, (GLuint s, GLsizei n, const GLchar* const* str, const GLint* len)) \
    X(void, CompileShader, (GLuint s))                                                       \
    X(void, GetShaderiv, (GLuint s, GLenum pname, GLint* params))                            \
    X(void, GetShaderInfoLog, (GLuint s, GLsizei max, GLsizei* len, GLchar* log))            \
    X(void, DeleteShader, (GLuint s))                                                        \
    X(GLuint, CreateProgram, ())                                                             \
    X(void, AttachShader, (GLuint p, GLuint s))                                              \
    X(void, LinkProgram, (GLuint p))                                                         \
    X(void, GetProgramiv, (GLuint p, GLenum pname, GLint* params))                           \
    X(void, GetProgramInfoLog, (GLuint p, GLsizei max, GLsizei* len, GLchar* log))           \
    X(void, DeleteProgram, (GLuint p))                                                       \
    X(void, UseProgram, (GLuint p))                                                          \
    X(GLint, GetUniformLocation, (GLuint p, const GLchar* name))                             \
    X(void, GetUniformiv, (GLuint p, GLint loc, GLint* params))                              \
    X(void, ProgramUniform1i, (GLuint p, GLint loc, GLint v))                                \
    X(void, ProgramUniform2i, (GLuint p, GLint loc, GLint a, GLint b))                       \
    X(void, ProgramUniform1f, (GLuint p, GLint loc, GLfloat v))                              \
    X(void, ProgramUniform2f, (GLuint p, GLint loc, GLfloat a, GLfloat b))                   \
    X(void, ProgramUniform3fv, (GLuint p, GLint loc, GLsizei n, const GLfloat* v))           \
    X(void, ProgramUniform4fv, (GLuint p, GLint loc, GLsizei n, const GLfloat* v))           \
    X(void, ProgramUniform1iv, (GLuint p, GLint loc, GLsizei n, const GLint* v))             \
    X(void, ProgramUniform1fv, (GLuint p, GLint loc, GLsizei n, const GLfloat* v))           \
    X(void, ProgramUniform2fv, (GLuint p, GLint loc, GLsizei n, const GLfloat* v))           \
    X(void, ProgramUniformMatrix4fv,                                                         \
      (GLuint p, GLint loc, GLsizei n, GLboolean transpose, const GLfloat* v))               \
    X(void, CreateTextures, (GLenum target, GLsizei n, GLuint* textures))                    \
    X(void, TextureStorage2D, (GLuint t, GLsizei levels, GLenum fmt, GLsizei w, GLsizei h))  \
    X(void, TextureSubImage2D, (GLuint t, GLint level, GLint x, GLint y, GLsizei w,          \
                                GLsizei h, GLenum format, GLenum type, const void* pixels))  \
    X(void, TextureParameteri, (GLuint t, GLenum pname, GLint param))                        \
    X(void, GetTextureImage, (GLuint t, GLint level, GLenum format, GLenum type,             \
                              GLsizei bufSize, void* pixels))                                \
    X(void, BindTextureUnit, (GLuint unit, GLuint t))                                        \
    X(void, BindImageTexture, (GLuint unit, GLuint t, GLint level, GLboolean layered,        \
                               GLint layer, GLenum access, GLenum format))                   \
    X(void, ClearTexImage, (GLuint t, GLint level, GLenum format, GLenum type,               \
                            const void* data))                                               \
    X(void, DeleteTextures, (GLsizei n, const GLuint* textures))                             \
    X(void, CreateFramebuffers, (GLsizei n, GLuint* fbs))                                    \
    X(void, NamedFramebufferTexture, (GLuint fb, GLenum attachment, GLuint t, GLint level))  \
    X(void, NamedFramebufferDrawBuffers, (GLuint fb, GLsizei n, const GLenum* bufs))         \
    X(GLenum, CheckNamedFramebufferStatus, (GLuint fb, GLenum target))                       \
    X(void, ClearNamedFramebufferfv, (GLuint fb, GLenum buffer, GLint drawbuffer,            \
                                      const GLfloat* value))                                 \
    X(void, BindFramebuffer, (GLenum target, GLuint fb))                                     \
    X(void, DeleteFramebuffers, (GLsizei n, const GLuint* fbs))                              \
    X(void, CreateBuffers, (GLsizei n, GLuint* buffers))                                     \
    X(void, NamedBufferStorage, (GLuint b, GLsizeiptr size, const void* data, GLbitfield f)) \
    X(void, GetNamedBufferSubData, (GLuint b, GLintptr off, GLsizeiptr size, void* data))    \
    X(void, BindBufferBase, (GLenum target, GLuint index, GLuint buffer))                    \
    X(void, DeleteBuffers, (GLsizei n, const GLuint* buffers))                               \
    X(void, CreateVertexArrays, (GLsizei n, GLuint* arrays))                                 \
    X(void, VertexArrayVertexBuffer, (GLuint va, GLuint bindingindex, GLuint buffer,         \
                                      GLintptr offset, GLsizei stride))                      \
    X(void, VertexArrayElementBuffer, (GLuint va, GLuint buffer))                            \
    X(void, VertexArrayAttribFormat, (GLuint va, GLuint attrib, GLint size, GLenum type,     \
                                      GLboolean normalized, GLuint relativeoffset))          \
    X(void, VertexArrayAttribBinding, (GLuint va, GLuint attrib, GLuint bindingindex))       \
    X(void, EnableVertexArrayAttrib, (GLuint va, GLuint attrib))                             \
    X(void, BindVertexArray, (GLuint va))                                                    \
    X(void, DeleteVertexArrays, (GLsizei n, const GLuint* arrays))                           \
    X(void, DrawElementsBaseVertex, (GLenum mode, GLsizei count, GLenum type,                \
                                     const void* indices, GLint basevertex))                 \
    X(void, DispatchCompute, (GLuint x, GLuint y, GLuint z))                                 \
    X(void, DrawArrays, (GLenum mode, GLint first, GLsizei count))                           \
    X(void, ReadPixels, (GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type, \
                         void* pixels))                                                      \
    X(void, ReadBuffer, (GLenum mode))                                                       \
    X(void, MemoryBarrier, (GLbitfield barriers))

namespace gl {
#define SL_GL_DECLARE(ret, name, params) using name##Fn = ret(APIENTRYP) params; extern name##Fn name;
SL_GL_FUNCTIONS(SL_GL_DECLARE)
#undef SL_GL_DECLARE
}  // namespace gl

namespace sl {

using GlProc = void (*)();
using GetProcAddress = GlProc (*)(const char* name, void* user);

// Resolves every function of SL_GL_FUNCTIONS through `getProc`. Returns the names that could
// not be resolved (empty on success); callers treat a non-empty list as fatal.
std::string loadGlFunctions(GetProcAddress getProc, void* user);

// glGetString as std::string ("" for null).
std::string glString(GLenum name);

}  // namespace sl
