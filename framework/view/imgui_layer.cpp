// ImGuiLayer: see imgui_layer.h.
#include "imgui_layer.h"

#include "imgui_gl_loader.h"

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

namespace sl {

ImGuiLayer::ImGuiLayer(GlfwWindow& window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini in the working directory: same start every time
    io.LogFilename = nullptr;
    ImGui::StyleColorsDark();
    // install_callbacks: ImGui chains to the window's own key callback, installed before it.
    if (!ImGui_ImplGlfw_InitForOpenGL(window.handle(), true)) {
        ImGui::DestroyContext();
        throw BackendError("Dear ImGui: the GLFW backend did not initialise");
    }
    // Init loads GL through gl3w's glX path first (and reads the GL version with it); the
    // entry points are then taken from the window's context, like gl::.
    if (!ImGui_ImplOpenGL3_Init("#version 410 core") || !resolveImGuiGlThroughGlfw()) {
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        throw BackendError("Dear ImGui: the OpenGL3 backend found no OpenGL 3+ entry points "
                           "(apt-get install libgl1 libglx-mesa0; or run the viewer with --no-panels)");
    }
}

ImGuiLayer::~ImGuiLayer() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void ImGuiLayer::beginFrame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void ImGuiLayer::endFrame() {
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

bool ImGuiLayer::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace sl
