// imgui_gl_loader: points ImGui's OpenGL3 backend (its gl3w copy, imgl3w) at the GL entry
// points of the current window context. Its own file because ImGui's loader header declares
// GL types of its own, which must not meet <GL/glcorearb.h> (gl_api.h).
#pragma once

namespace sl {

// Re-resolves every function of ImGui's OpenGL3 backend through glfwGetProcAddress.
// Returns false if the context is not OpenGL 3 or newer.
bool resolveImGuiGlThroughGlfw();

}  // namespace sl
