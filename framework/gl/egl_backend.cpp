// EGL backend: Mesa's surfaceless platform (EGL_MESA_platform_surfaceless), a context with no
// surface at all (EGL_KHR_surfaceless_context); Shadowlab draws into framebuffer objects.
#include "gl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>

namespace sl {
namespace {

std::string eglErrorName(EGLint code) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "EGL error 0x%04x", code);
    return buf;
}

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const size_t n = std::strlen(name);
    for (const char* p = std::strstr(list, name); p; p = std::strstr(p + 1, name))
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

class EglContextImpl final : public GlContext {
public:
    EglContextImpl() {
        const char* clientExt = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        if (!hasExtension(clientExt, "EGL_MESA_platform_surfaceless"))
            throw BackendError("EGL has no EGL_MESA_platform_surfaceless — apt-get install "
                               "libegl-mesa0 libgl1-mesa-dri");
        auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
            eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (!getPlatformDisplay) throw BackendError("eglGetPlatformDisplayEXT not found");
        display_ = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        EGLint major = 0, minor = 0;
        if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor))
            throw BackendError("eglInitialize(surfaceless) failed: " + eglErrorName(eglGetError()));
        const char* ext = eglQueryString(display_, EGL_EXTENSIONS);
        if (!hasExtension(ext, "EGL_KHR_surfaceless_context") ||
            !hasExtension(ext, "EGL_KHR_no_config_context"))
            throw BackendError("EGL display lacks surfaceless or no-config contexts");
        if (!eglBindAPI(EGL_OPENGL_API)) throw BackendError("eglBindAPI(OpenGL) failed");
        const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                                  EGL_CONTEXT_MINOR_VERSION, 5,
                                  EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                  EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                  EGL_NONE};
        context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
        if (context_ == EGL_NO_CONTEXT)
            throw BackendError("eglCreateContext(4.5 core) failed: " +
                               eglErrorName(eglGetError()));
        makeCurrent();
        finishContextSetup(*this, info_, "egl");
    }
    ~EglContextImpl() override {
        if (display_ != EGL_NO_DISPLAY) {
            eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
            eglTerminate(display_);
        }
    }
    GlProc getProcAddress(const char* name) override {
        return reinterpret_cast<GlProc>(eglGetProcAddress(name));
    }
    void makeCurrent() override {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw BackendError("eglMakeCurrent failed: " + eglErrorName(eglGetError()));
    }

private:
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> createEglContext() { return std::make_unique<EglContextImpl>(); }

}  // namespace sl
