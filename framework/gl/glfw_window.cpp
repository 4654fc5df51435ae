// GlfwWindow: GLFW window + context (see glfw_window.h).
#include "glfw_window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>

namespace sl {

bool displayAvailable() {
    const char* x = std::getenv("DISPLAY");
    const char* w = std::getenv("WAYLAND_DISPLAY");
    return (x && *x) || (w && *w);
}

GlfwWindow::GlfwWindow(int width, int height, const std::string& title) {
    if (!displayAvailable())
        throw BackendError("no display ($DISPLAY / $WAYLAND_DISPLAY unset): use `render`, "
                           "which needs none");
    if (!glfwInit()) throw BackendError("glfwInit failed (is the display reachable?)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        throw BackendError("GLFW could not create a 4.5 core window — apt-get install "
                           "libgl1-mesa-dri libglx-mesa0");
    }
    glfwSetWindowUserPointer(window_, this);
    glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
        if (action == GLFW_PRESS || action == GLFW_REPEAT)
            static_cast<GlfwWindow*>(glfwGetWindowUserPointer(w))->keys_.push_back(key);
    });
    makeCurrent();
    glfwSwapInterval(1);
    finishContextSetup(*this, info_, "glfw");
}

GlfwWindow::~GlfwWindow() {
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

GlProc GlfwWindow::getProcAddress(const char* name) {
    return reinterpret_cast<GlProc>(glfwGetProcAddress(name));
}

void GlfwWindow::makeCurrent() { glfwMakeContextCurrent(window_); }
bool GlfwWindow::shouldClose() const { return glfwWindowShouldClose(window_); }
void GlfwWindow::swapBuffers() { glfwSwapBuffers(window_); }
void GlfwWindow::pollEvents() { glfwPollEvents(); }

std::vector<int> GlfwWindow::takeKeyPresses() {
    std::vector<int> out;
    out.swap(keys_);
    return out;
}

int GlfwWindow::width() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return w;
}

int GlfwWindow::height() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return h;
}

}  // namespace sl
