// GlfwWindow: a window with its own OpenGL 4.5 core context, from GLFW — the interactive
// backend. It is one more GlContext: the renderer runs in it unchanged, and the gl:: entry
// points are resolved through glfwGetProcAddress.
#pragma once

#include "gl_context.h"

#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace sl {

class GlfwWindow final : public GlContext {
public:
    // Throws BackendError when no display can be opened (no $DISPLAY / $WAYLAND_DISPLAY).
    GlfwWindow(int width, int height, const std::string& title);
    ~GlfwWindow() override;

    GlProc getProcAddress(const char* name) override;
    void makeCurrent() override;

    bool shouldClose() const;
    void swapBuffers();
    void pollEvents();
    // Keys pressed since the last call, as GLFW key codes, oldest first.
    std::vector<int> takeKeyPresses();
    int width() const;   // framebuffer size in pixels
    int height() const;
    GLFWwindow* handle() const { return window_; }  // for ImGui's GLFW backend (ImGuiLayer)

private:
    GLFWwindow* window_ = nullptr;
    std::vector<int> keys_;
};

// True if a display is there to open a window on.
bool displayAvailable();

}  // namespace sl
