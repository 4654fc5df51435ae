// GlContext: an OpenGL 4.5 core context made current on this thread, from one backend.
//
// Backends: OSMesa (dlopen()ed, renders into a small client buffer; Shadowlab draws into its
// own framebuffers) and EGL surfaceless (Mesa). A window backend (GLFW) implements the same
// interface: it adds a surface, nothing in the renderer changes.
#pragma once

#include "gl_api.h"

#include <memory>
#include <stdexcept>
#include <string>

namespace sl {

enum class BackendKind { Auto, OSMesa, Egl };

BackendKind parseBackendKind(const std::string& name);  // "auto" | "osmesa" | "egl"
const char* toString(BackendKind);

// No backend could give a 4.5 core context. what() lists every attempt, why it failed, and
// which Debian package provides the missing piece.
class BackendError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct ContextInfo {
    std::string backend;    // "osmesa" | "egl"
    std::string vendor;     // GL_VENDOR
    std::string renderer;   // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string version;    // GL_VERSION, e.g. "4.5 (Core Profile) Mesa 22.3.6"
    std::string mesaVersion;  // "22.3.6", parsed from GL_VERSION ("" if not Mesa)
    std::string choice;     // why this backend: "asked for", or `auto`'s reason
    bool isSoftware() const;  // llvmpipe / softpipe
};

class GlContext {
public:
    virtual ~GlContext() = default;
    virtual GlProc getProcAddress(const char* name) = 0;
    virtual void makeCurrent() = 0;
    // Makes this context current again and re-resolves gl:: through it (after another
    // context, of any backend, was current on this thread).
    void activate();
    const ContextInfo& info() const { return info_; }
    void noteChoice(std::string why) { info_.choice = std::move(why); }

protected:
    ContextInfo info_;
};

// Creates a context, makes it current and loads the gl:: functions. `Auto` takes OSMesa if
// libOSMesa can be loaded and EGL otherwise (info().choice says which and why). Unless SHADOWLAB_ALLOW_HARDWARE=1, Mesa is asked
// for llvmpipe (LIBGL_ALWAYS_SOFTWARE, GALLIUM_DRIVER) so that images are reproducible.
std::unique_ptr<GlContext> createContext(BackendKind kind);

// Backend constructors; each throws BackendError with its own reason.
std::unique_ptr<GlContext> createOSMesaContext();
std::unique_ptr<GlContext> createEglContext();

// Loads the driver library of `kind` (Auto, OSMesa: libOSMesa, with LLVM) without creating a
// context or a thread, and returns whether it loaded. A process that forks workers without exec
// (the grader) calls it once first: every child then inherits the loaded and relocated library
// instead of loading it anew (about a quarter of a grade's page faults). EGL: nothing to do.
bool preloadDriver(BackendKind kind);

// "" when libOSMesa loads (the library stays loaded), else why not: built without OSMesa's
// header, or the library is missing. Tests skip an OSMesa check with it.
std::string whyNoOSMesa();

// Fills `info` from the current context and loads gl::. Shared by the backends.
void finishContextSetup(GlContext& context, ContextInfo& info, const std::string& backend);

}  // namespace sl
