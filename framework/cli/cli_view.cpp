// cli_view: `shadowlab view` — the interactive window (GLFW). Renders a scene through a
// solution with the same Renderer as `render`, shows one of its images, and re-renders on
// keys: 1-4 pick the image, arrows orbit the camera, R reloads the shaders (edit, press R,
// look), Esc quits. --frames/--screenshot make it scriptable (tests, screenshots).
#include "cli_commands.h"
#include "glfw_window.h"
#include "image_io.h"
#include "paths.h"
#include "renderer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <glm/gtc/matrix_transform.hpp>

#include <iostream>
#include <memory>

namespace sl::cli {
namespace {

const char* kImages[] = {"final", "shadow", "moments_raw", "moments_filtered"};

Texture uploadForDisplay(const Image& image) {
    Image rgba(image.width, image.height, image.channels == 1 ? 1 : 4, 1.0f);
    for (size_t i = 0, n = size_t(image.width) * image.height; i < n; ++i)
        for (int c = 0; c < std::min(image.channels, rgba.channels); ++c)
            rgba.pixels[i * rgba.channels + c] = image.pixels[i * image.channels + c];
    Texture t = Texture::create(image.width, image.height,
                                rgba.channels == 1 ? GL_R32F : GL_RGBA32F, GL_LINEAR);
    t.upload(rgba);
    return t;
}

// Rotates the camera about its target: yaw around +y, pitch toward +y.
void orbit(Camera& cam, float yawDegrees, float pitchDegrees) {
    glm::vec3 offset = cam.position - cam.target;
    offset = glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(yawDegrees), {0, 1, 0}) *
                       glm::vec4(offset, 0.0f));
    glm::vec3 side = glm::normalize(glm::cross(offset, glm::vec3(0, 1, 0)));
    glm::vec3 pitched = glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(pitchDegrees), side) *
                                  glm::vec4(offset, 0.0f));
    if (std::abs(glm::normalize(pitched).y) < 0.98f) offset = pitched;
    cam.position = cam.target + offset;
}

int runView(const std::string& scenePath, const std::string& solution, int frames,
            const std::string& screenshot) {
    Scene scene = loadScene(scenePath);
    const fs::path solutionDir = resolveSolution(solution);
    Camera& cam = scene.cameras.front();
    GlfwWindow window(cam.width, cam.height, "shadowlab — " + scene.name);
    std::cout << "viewer: " << window.info().renderer << "\n"
              << "keys: 1 final  2 shadow G  3 moments  4 filtered moments  arrows orbit  "
                 "R reload shaders  Esc quit\n";
    auto library = [&] { return ShaderLibrary::forSolution(solutionDir, repoRoot()); };
    auto renderer = std::make_unique<Renderer>(library());
    GlProgram present = GlProgram::graphics(library(), "present.vert", "present.frag", {});
    GLuint vao = 0;
    gl::CreateVertexArrays(1, &vao);
    VertexArrayHandle emptyVao(vao);  // core profile draws need a bound VAO

    int shown = 0;
    RenderResult result;
    Texture texture;
    bool dirty = true;
    for (int frame = 0; !window.shouldClose() && (frames <= 0 || frame < frames); ++frame) {
        if (dirty) {
            result = renderer->render(scene, planPasses(scene));
            for (const auto& note : result.stubNotes) std::cout << "note: " << note << "\n";
            dirty = false;
        }
        auto it = result.images.find(kImages[shown]);
        if (it == result.images.end()) it = result.images.find("final");
        texture = uploadForDisplay(it->second);
        gl::BindFramebuffer(GL_FRAMEBUFFER, 0);
        gl::Viewport(0, 0, window.width(), window.height());
        gl::Disable(GL_DEPTH_TEST);
        present.use();
        present.set("uImage", 0);
        present.set("uChannels", it->second.channels);
        present.set("uEncodeSrgb", it->first == "final" ? 1 : 0);
        gl::BindTextureUnit(0, texture.id());
        gl::BindVertexArray(emptyVao.id());
        gl::DrawArrays(GL_TRIANGLES, 0, 3);
        gl::BindVertexArray(0);
        if (!screenshot.empty() && frames > 0 && frame == frames - 1) {
            Image shot(window.width(), window.height(), 4);
            std::vector<unsigned char> bytes(shot.pixels.size());
            gl::ReadBuffer(GL_BACK);
            gl::PixelStorei(GL_PACK_ALIGNMENT, 1);
            gl::ReadPixels(0, 0, shot.width, shot.height, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
            for (size_t i = 0; i < bytes.size(); ++i) shot.pixels[i] = bytes[i] / 255.0f;
            writePngPreview(shot, screenshot, false);
            std::cout << "wrote " << screenshot << "\n";
        }
        window.swapBuffers();
        window.pollEvents();
        for (int key : window.takeKeyPresses()) {
            if (key >= GLFW_KEY_1 && key <= GLFW_KEY_4) shown = key - GLFW_KEY_1;
            if (key == GLFW_KEY_LEFT) orbit(cam, -10, 0), dirty = true;
            if (key == GLFW_KEY_RIGHT) orbit(cam, 10, 0), dirty = true;
            if (key == GLFW_KEY_UP) orbit(cam, 0, 5), dirty = true;
            if (key == GLFW_KEY_DOWN) orbit(cam, 0, -5), dirty = true;
            if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) return Ok;
            if (key == GLFW_KEY_R) {
                try {  // a typo in the student's shader keeps the last image on screen
                    auto fresh = std::make_unique<Renderer>(library());
                    result = fresh->render(scene, planPasses(scene));
                    renderer = std::move(fresh);
                    std::cout << "reloaded shaders\n";
                } catch (const ShaderError& e) {
                    std::cerr << "shader error:\n" << e.what() << "\n";
                }
            }
        }
    }
    return Ok;
}

}  // namespace

void addViewCommand(CLI::App& app, Context& ctx) {
    auto* view = app.add_subcommand("view", "open a window on a scene (needs a display)");
    struct Args {
        std::string scene, solution = "reference", screenshot;
        int frames = 0;
    };
    auto a = std::make_shared<Args>();
    view->add_option("--scene", a->scene, "scene JSON file")->required();
    view->add_option("--solution", a->solution, "reference, student, or a folder");
    view->add_option("--frames", a->frames, "quit after this many frames (0: when closed)");
    view->add_option("--screenshot", a->screenshot, "PNG of the window's last frame (with --frames)");
    view->callback([a, &ctx] { ctx.exitCode = runView(a->scene, a->solution, a->frames, a->screenshot); });
}

}  // namespace sl::cli
