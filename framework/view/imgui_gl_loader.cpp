// imgui_gl_loader: see imgui_gl_loader.h.
#include "imgui_gl_loader.h"

#include <backends/imgui_impl_opengl3_loader.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace sl {

bool resolveImGuiGlThroughGlfw() {
    // GLFWglproc and GL3WglProc are both void (*)(void): glfwGetProcAddress is a gl3w getter.
    return imgl3wInit2(reinterpret_cast<GL3WGetProcAddressProc>(&glfwGetProcAddress)) == 0;
}

}  // namespace sl
