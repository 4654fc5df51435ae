// ImGuiLayer: Dear ImGui (Debian's libimgui-dev) on a GlfwWindow, with ImGui's own GLFW and
// OpenGL3 backends. Frame: beginFrame(), ImGui:: calls, endFrame() draws into the window's
// current framebuffer.
//
// ImGui's OpenGL3 backend loads GL through its own gl3w copy (glXGetProcAddress from a
// dlopen()ed libGL, RTLD_LOCAL). The layer re-resolves those entry points through
// glfwGetProcAddress, i.e. through the context that owns the window, as gl:: is; nothing
// links libGL's gl* symbols, so the OSMesa/EGL separation (gl_api.h) holds.
#pragma once

#include "glfw_window.h"

namespace sl {

class ImGuiLayer {
public:
    explicit ImGuiLayer(GlfwWindow& window);  // throws BackendError
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void beginFrame();
    void endFrame();
    // A widget has the keyboard (e.g. typing a number): keys are not the viewer's shortcuts.
    bool wantsKeyboard() const;
};

}  // namespace sl
