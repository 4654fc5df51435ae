// gl_api: storage and resolution of the gl:: function pointers (see gl_api.h).
#include "gl_api.h"

namespace gl {
#define SL_GL_DEFINE(ret, name, params) name##Fn name = nullptr;
SL_GL_FUNCTIONS(SL_GL_DEFINE)
#undef SL_GL_DEFINE
}  // namespace gl

namespace sl {

std::string loadGlFunctions(GetProcAddress getProc, void* user) {
    std::string missing;
#define SL_GL_RESOLVE(ret, name, params)                                            \
    gl::name = reinterpret_cast<gl::name##Fn>(getProc("gl" #name, user));           \
    if (!gl::name) missing += (missing.empty() ? "gl" : ", gl") + std::string(#name);
    SL_GL_FUNCTIONS(SL_GL_RESOLVE)
#undef SL_GL_RESOLVE
    return missing;
}

std::string glString(GLenum name) {
    const GLubyte* s = gl::GetString(name);
    return s ? reinterpret_cast<const char*>(s) : "";
}

}  // namespace sl
