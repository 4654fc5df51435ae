// OSMesa backend: libOSMesa is dlopen()ed with RTLD_LOCAL so that its gl* exports never
// interpose on libGL/libEGL's, and every GL function is taken from OSMesaGetProcAddress.
// Mesa >= 25.1 dropped OSMesa: a build without its header (SHADOWLAB_HAVE_OSMESA unset) has the
// stub at the end of this file, and `auto` falls back to EGL.
#include "gl_context.h"

#if SHADOWLAB_HAVE_OSMESA
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace sl {
namespace {

using CreateContextAttribsFn = OSMesaContext (*)(const int*, OSMesaContext);
using MakeCurrentFn = GLboolean (*)(OSMesaContext, void*, GLenum, GLsizei, GLsizei);
using DestroyContextFn = void (*)(OSMesaContext);
using GetProcAddressFn = OSMESAproc (*)(const char*);

// Loads libOSMesa (RTLD_NOW | RTLD_LOCAL) or throws BackendError naming the package. Loading
// it again returns the same handle: the library stays loaded for the process's lifetime.
void* loadOSMesa() {
    // $SHADOWLAB_OSMESA_LIBRARY names a libOSMesa outside the loader's path.
    std::vector<std::string> names = {"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"};
    if (const char* path = std::getenv("SHADOWLAB_OSMESA_LIBRARY"); path && *path)
        names = {path};
    std::string errors;
    for (const auto& name : names) {
        if (void* library = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL)) return library;
        errors += std::string(" ") + dlerror() + ";";
    }
    throw BackendError("cannot load libOSMesa (" + errors + ") — apt-get install libosmesa6");
}

class OSMesaContextImpl final : public GlContext {
public:
    OSMesaContextImpl() {
        library_ = loadOSMesa();
        create_ = reinterpret_cast<CreateContextAttribsFn>(
            dlsym(library_, "OSMesaCreateContextAttribs"));
        makeCurrent_ = reinterpret_cast<MakeCurrentFn>(dlsym(library_, "OSMesaMakeCurrent"));
        destroy_ = reinterpret_cast<DestroyContextFn>(dlsym(library_, "OSMesaDestroyContext"));
        getProc_ = reinterpret_cast<GetProcAddressFn>(dlsym(library_, "OSMesaGetProcAddress"));
        if (!create_ || !makeCurrent_ || !destroy_ || !getProc_)
            throw BackendError("libOSMesa lacks OSMesaCreateContextAttribs (Mesa too old)");
        const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA,
                               OSMESA_DEPTH_BITS, 24,
                               OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION, 4,
                               OSMESA_CONTEXT_MINOR_VERSION, 5,
                               0};
        context_ = create_(attribs, nullptr);
        if (!context_) throw BackendError("OSMesaCreateContextAttribs(4.5 core) failed");
        // OSMesa needs a client buffer to make a context current; all real drawing goes to
        // framebuffer objects, so a tiny one does.
        buffer_.assign(16 * 16 * 4, 0);
        makeCurrent();
        finishContextSetup(*this, info_, "osmesa");
    }
    ~OSMesaContextImpl() override {
        if (context_) destroy_(context_);
        // The library stays loaded: llvmpipe's threads may outlive the context briefly.
    }
    GlProc getProcAddress(const char* name) override {
        return reinterpret_cast<GlProc>(getProc_(name));
    }
    void makeCurrent() override {
        if (!makeCurrent_(context_, buffer_.data(), GL_UNSIGNED_BYTE, 16, 16))
            throw BackendError("OSMesaMakeCurrent failed");
    }

private:
    void* library_ = nullptr;
    CreateContextAttribsFn create_ = nullptr;
    MakeCurrentFn makeCurrent_ = nullptr;
    DestroyContextFn destroy_ = nullptr;
    GetProcAddressFn getProc_ = nullptr;
    OSMesaContext context_ = nullptr;
    std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<GlContext> createOSMesaContext() {
    return std::make_unique<OSMesaContextImpl>();
}

std::string whyNoOSMesa() {
    try {
        loadOSMesa();
        return "";
    } catch (const BackendError& e) {
        return e.what();
    }
}

}  // namespace sl

#else  // built without OSMesa's header

namespace sl {

const char* const kNoOSMesaBuild =
    "this shadowlab was built without OSMesa (CMake found no osmesa.pc: Mesa 25.1 and later ship "
    "none); the egl backend renders the same images";

std::unique_ptr<GlContext> createOSMesaContext() { throw BackendError(kNoOSMesaBuild); }

std::string whyNoOSMesa() { return kNoOSMesaBuild; }

}  // namespace sl

#endif
