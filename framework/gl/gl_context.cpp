// Backend selection and the setup every backend shares (see gl_context.h).
#include "gl_context.h"

#include <cstdlib>
#include <regex>

namespace sl {

BackendKind parseBackendKind(const std::string& name) {
    if (name == "auto") return BackendKind::Auto;
    if (name == "osmesa") return BackendKind::OSMesa;
    if (name == "egl") return BackendKind::Egl;
    throw std::invalid_argument("unknown backend '" + name + "': expected auto, osmesa or egl");
}

const char* toString(BackendKind kind) {
    switch (kind) {
        case BackendKind::Auto: return "auto";
        case BackendKind::OSMesa: return "osmesa";
        case BackendKind::Egl: return "egl";
    }
    return "?";
}

bool ContextInfo::isSoftware() const {
    return renderer.find("llvmpipe") != std::string::npos ||
           renderer.find("softpipe") != std::string::npos;
}

static void requestSoftwareRenderer() {
    const char* allow = std::getenv("SHADOWLAB_ALLOW_HARDWARE");
    if (allow && std::string(allow) == "1") return;
    // overwrite = 0: a user who set these on purpose keeps them.
    setenv("LIBGL_ALWAYS_SOFTWARE", "1", 0);
    setenv("GALLIUM_DRIVER", "llvmpipe", 0);
}

// What to install for a software renderer on this build's release: no libosmesa6 where the
// build found no OSMesa (its Mesa has none).
static std::string installAdvice() {
#if SHADOWLAB_HAVE_OSMESA
    return "apt-get install libosmesa6 libegl-mesa0 libgl1-mesa-dri";
#else
    return "apt-get install libegl-mesa0 libgl1-mesa-dri";
#endif
}

std::unique_ptr<GlContext> createContext(BackendKind kind) {
    requestSoftwareRenderer();
    std::unique_ptr<GlContext> context;
    if (kind != BackendKind::Auto) {
        context = kind == BackendKind::OSMesa ? createOSMesaContext() : createEglContext();
        context->noteChoice(std::string("asked for (--backend ") + toString(kind) + ")");
        return context;
    }
    // OSMesa first where it loads: the kit's goldens were made through it. EGL gives the same
    // bytes (Determinism.* checks it wherever both are present).
    std::string osmesaFailure = whyNoOSMesa();
    if (osmesaFailure.empty()) {
        try {
            context = createOSMesaContext();
            context->noteChoice("auto: libOSMesa loads, and auto takes it first");
            return context;
        } catch (const BackendError& e) {
            osmesaFailure = e.what();
        }
    }
    try {
        context = createEglContext();
        context->noteChoice("auto: no usable OSMesa (" + osmesaFailure + "), so EGL");
        return context;
    } catch (const BackendError& e) {
        throw BackendError("no backend gave an OpenGL 4.5 core context. Tried:\n  osmesa: " +
                           osmesaFailure + "\n  egl: " + e.what() +
                           "\nInstall Mesa's software renderer: " + installAdvice() +
                           " (or run ./kit, which does it)");
    }
}

bool preloadDriver(BackendKind kind) {
    return kind != BackendKind::Egl && whyNoOSMesa().empty();
}

void GlContext::activate() {
    makeCurrent();
    ContextInfo info = info_;
    finishContextSetup(*this, info, info_.backend);
}

void finishContextSetup(GlContext& context, ContextInfo& info, const std::string& backend) {
    struct Thunk {
        static GlProc resolve(const char* name, void* self) {
            return static_cast<GlContext*>(self)->getProcAddress(name);
        }
    };
    std::string missing = loadGlFunctions(&Thunk::resolve, &context);
    if (!missing.empty())
        throw BackendError(backend + " context lacks OpenGL functions: " + missing);
    info.backend = backend;
    info.vendor = glString(GL_VENDOR);
    info.renderer = glString(GL_RENDERER);
    info.version = glString(GL_VERSION);
    GLint major = 0, minor = 0;
    gl::GetIntegerv(GL_MAJOR_VERSION, &major);
    gl::GetIntegerv(GL_MINOR_VERSION, &minor);
    if (major * 10 + minor < 45)
        throw BackendError(backend + " gave OpenGL " + info.version + ", 4.5 core is needed");
    std::smatch m;
    if (std::regex_search(info.version, m, std::regex("Mesa ([0-9][0-9.]*)")))
        info.mesaVersion = m[1];
}

}  // namespace sl
