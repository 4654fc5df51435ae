// cli_view: `shadowlab view` — the interactive window (GLFW + Dear ImGui). Renders a scene
// through a solution with the same Renderer as `render` and shows one of its images, with a
// panel beside it: the shadow settings, the image shown, and the time of each pass. Changing
// a setting re-plans and re-renders. Keys: 1-4 pick the image, arrows orbit the camera,
// R reloads the shaders (edit, press R, look), Esc quits.
// Scriptable (tests, screenshots): each --set key=value is applied on its own frame from the
// second one on, exactly as the panel applies a change; --frames or --screenshot end the run.
#include "cli_commands.h"
#include "editable_scene.h"
#include "glfw_window.h"
#include "image_io.h"
#include "imgui_layer.h"
#include "paths.h"
#include "renderer.h"
#include "stub_survey.h"
#include "view_options.h"
#include "view_panels.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

namespace sl::cli {
namespace {

constexpr int kPanelWidth = 380;      // the panel column, right of the image
constexpr int kPanelMinHeight = 720;  // room for the settings and a timing table

const char* kKeyImages[] = {"final", "shadow", "moments_raw", "moments_filtered"};

// The image as the window shows it: RGBA or grey; `channel` >= 0 picks one channel as grey.
Texture uploadForDisplay(const Image& image, int channel) {
    const bool grey = image.channels == 1 || channel >= 0;
    Image shown(image.width, image.height, grey ? 1 : 4, 1.0f);
    for (size_t i = 0, n = size_t(image.width) * image.height; i < n; ++i)
        for (int c = 0; c < shown.channels && c < image.channels; ++c)
            shown.pixels[i * shown.channels + c] =
                image.pixels[i * image.channels + (channel >= 0 ? channel : c)];
    Texture t = Texture::create(image.width, image.height, grey ? GL_R32F : GL_RGBA32F, GL_LINEAR);
    t.upload(shown);
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

// One setting, from the panel (JSON value) or from --set (text): view.* or a scene key.
// Throws SceneError (scene keys) or std::invalid_argument (view keys).
void applySetting(EditableScene& scene, ViewOptions& options, const std::string& key,
                  const nlohmann::json& value) {
    if (setViewOption(options, key, value.is_string() ? value.get<std::string>() : value.dump()))
        return;
    try {
        scene.set(key, value);
    } catch (const SceneError& e) {
        throw SceneError("--set " + key + "=" + (value.is_string() ? value.get<std::string>()
                                                                   : value.dump()) + ": " + e.what());
    }
}
void applySetting(EditableScene& scene, ViewOptions& options, const std::string& setting) {
    auto [key, text] = splitSetting(setting);
    if (setViewOption(options, key, text)) return;
    nlohmann::json value = nlohmann::json::parse(text, nullptr, false);
    applySetting(scene, options, key, value.is_discarded() ? nlohmann::json(text) : value);
}

// "plan (vsm, sat): shadow sat-rows sat-columns lighting", printed on each re-plan.
std::string planLine(const Scene& scene, const PassPlan& plan) {
    std::string line = std::string("plan (") + toString(scene.shadow.technique) + ", " +
                       toString(scene.shadow.filter) + "):";
    for (const auto& p : plan.passes) line += std::string(" ") + toString(p.kind);
    return line;
}

struct ViewArgs {
    std::string scene, solution = defaultSolution(), screenshot;
    int frames = 0;
    std::vector<std::string> sets;
    bool noPanels = false;
};

int runView(ViewArgs a) {
    // A screenshot without --frames: one frame per --set and one more, then the PNG and quit.
    if (!a.screenshot.empty() && a.frames <= 0) a.frames = int(a.sets.size()) + 2;
    EditableScene edits(a.scene);
    ViewOptions options;
    try {  // every --set is checked before a window opens: a typo fails at once, display or not
        EditableScene check = edits;
        ViewOptions checkOptions;
        for (const auto& s : a.sets) applySetting(check, checkOptions, s);
    } catch (const std::exception& e) {
        std::cerr << "bad setting: " << e.what() << "\n";
        return BadInput;
    }
    if (a.frames > 0 && a.frames <= int(a.sets.size())) {
        std::cerr << "bad setting: --frames " << a.frames << ": expected more frames than --set "
                  << "edits (" << a.sets.size() << "; one per frame from the second)\n";
        return BadInput;
    }
    const fs::path solutionDir = resolveSolution(a.solution);
    const Camera first = edits.scene().cameras.front();
    const int panelWidth = a.noPanels ? 0 : kPanelWidth;
    GlfwWindow window(first.width + panelWidth,
                      a.noPanels ? first.height : std::max(first.height, kPanelMinHeight),
                      "shadowlab — " + edits.scene().name);
    std::cout << "viewer: " << window.info().renderer << "\n"
              << "keys: 1 final  2 shadow G  3 moments  4 filtered moments  arrows orbit  "
                 "R reload shaders  Esc quit\n";
    std::unique_ptr<ImGuiLayer> ui;
    if (!a.noPanels) ui = std::make_unique<ImGuiLayer>(window);
    auto library = [&] { return ShaderLibrary::forSolution(solutionDir, repoRoot()); };
    auto renderer = std::make_unique<Renderer>(library());
    GlProgram present = GlProgram::graphics(library(), "present.vert", "present.frag", {});
    GLuint vao = 0;
    gl::CreateVertexArrays(1, &vao);
    VertexArrayHandle emptyVao(vao);  // core profile draws need a bound VAO

    std::optional<glm::vec3> orbited;  // the camera's position once the arrows moved it
    auto shownScene = [&] {  // the scene as edited, with only the camera the window shows
        Scene s = edits.scene();
        s.cameras.resize(1);
        if (orbited) s.cameras.front().position = *orbited;
        return s;
    };
    // The image area, left of the panel: the first camera's size. A map of another size
    // (moments: mapSize²) is scaled to fit, keeping its aspect.
    const int areaWidth = first.width, areaHeight = first.height;
    PassPlan plan;
    RenderResult result;
    std::string lastError;
    bool dirty = true;
    size_t nextSet = 0;
    // The filtered map of a SAT scene costs a pass of its own: made only while it is shown.
    auto planOptions = [&] {
        return PlanOptions{.resolveSat = options.image.rfind("moments_filtered", 0) == 0};
    };
    for (int frame = 0; !window.shouldClose() && (a.frames <= 0 || frame < a.frames); ++frame) {
        if (frame > 0 && nextSet < a.sets.size()) {
            applySetting(edits, options, a.sets[nextSet++]);  // checked above: cannot throw
            dirty = true;
        }
        dirty = dirty || planOptions().resolveSat != plan.resolvedSat;
        if (dirty) {
            const Scene s = shownScene();
            plan = planPasses(s, planOptions());
            result = renderer->render(s, plan);
            completeStubNotes(renderer->library(), plan, result);  // one stub hides another
            if (frame > 0) std::cout << planLine(s, plan) << "\n";
            for (const auto& note : result.stubNotes) std::cout << "note: " << note << "\n";
            dirty = false;
        }
        auto it = result.images.find(options.image);
        if (it == result.images.end()) it = result.images.find("final");
        const int channel = options.channel < it->second.channels ? options.channel : -1;
        Texture texture = uploadForDisplay(it->second, channel);
        const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        gl::BindFramebuffer(GL_FRAMEBUFFER, 0);
        gl::ClearNamedFramebufferfv(0, GL_COLOR, 0, black);
        // The image at the window's top left; the camera's images one texel per pixel.
        const Image& image = it->second;
        const double scale = std::min(double(areaWidth) / image.width, double(areaHeight) / image.height);
        const int w = int(std::lround(image.width * scale)), h = int(std::lround(image.height * scale));
        gl::Viewport(0, window.height() - h, w, h);
        gl::Disable(GL_DEPTH_TEST);
        present.use();
        present.set("uImage", 0);
        present.set("uChannels", channel >= 0 ? 1 : it->second.channels);
        present.set("uEncodeSrgb", it->first.rfind("final", 0) == 0 && channel < 0 ? 1 : 0);
        gl::BindTextureUnit(0, texture.id());
        gl::BindVertexArray(emptyVao.id());
        gl::DrawArrays(GL_TRIANGLES, 0, 3);
        gl::BindVertexArray(0);
        std::vector<SettingEdit> panelEdits;
        if (ui) {
            ui->beginFrame();
            panelEdits = drawPanels(edits.scene(), plan, result, options, lastError,
                                    float(window.width() - panelWidth), float(panelWidth),
                                    float(window.height()));
            ui->endFrame();
        }
        if (!a.screenshot.empty() && a.frames > 0 && frame == a.frames - 1) {
            Image shot(window.width(), window.height(), 4);
            std::vector<unsigned char> bytes(shot.pixels.size());
            gl::ReadBuffer(GL_BACK);
            gl::PixelStorei(GL_PACK_ALIGNMENT, 1);
            gl::ReadPixels(0, 0, shot.width, shot.height, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
            for (size_t i = 0; i < bytes.size(); ++i) shot.pixels[i] = bytes[i] / 255.0f;
            if (const fs::path dir = fs::path(a.screenshot).parent_path(); !dir.empty())
                fs::create_directories(dir);
            writePngPreview(shot, a.screenshot, false);
            std::cout << "wrote " << a.screenshot << "\n";
        }
        window.swapBuffers();
        window.pollEvents();
        for (const auto& [key, value] : panelEdits) {
            try {
                applySetting(edits, options, key, value);
                lastError.clear();
                dirty = dirty || key.rfind("view.", 0) != 0;
            } catch (const std::exception& e) {  // the panel shows it; the scene stays as it was
                lastError = e.what();
                std::cerr << "bad setting: " << lastError << "\n";
            }
        }
        const bool typing = ui && ui->wantsKeyboard();
        for (int key : window.takeKeyPresses()) {
            if (typing) continue;
            if (key >= GLFW_KEY_1 && key <= GLFW_KEY_4) options.image = kKeyImages[key - GLFW_KEY_1];
            if (key >= GLFW_KEY_LEFT && key <= GLFW_KEY_UP) {
                Camera cam = shownScene().cameras.front();
                if (key == GLFW_KEY_LEFT) orbit(cam, -10, 0);
                if (key == GLFW_KEY_RIGHT) orbit(cam, 10, 0);
                if (key == GLFW_KEY_UP) orbit(cam, 0, 5);
                if (key == GLFW_KEY_DOWN) orbit(cam, 0, -5);
                orbited = cam.position;
                dirty = true;
            }
            if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) return Ok;
            if (key == GLFW_KEY_R) {
                try {  // a typo in the student's shader keeps the last image on screen
                    auto fresh = std::make_unique<Renderer>(library());
                    const Scene s = shownScene();
                    result = fresh->render(s, plan = planPasses(s, planOptions()));
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
    auto a = std::make_shared<ViewArgs>();
    view->add_option("--scene", a->scene, "scene JSON file")->required();
    view->add_option("--solution", a->solution, "reference, student, or a folder");
    view->add_option("--frames", a->frames, "quit after this many frames (0: when closed)");
    view->add_option("--screenshot", a->screenshot,
                     "PNG of the window's last frame, then quit (without --frames: after one frame "
                     "per --set and one more)");
    view->add_option("--set", a->sets,
                     "key=value, one per frame from the second, as the panel would: a scene key "
                     "(shadow.filter.type=sat, shadow.filter.radius=8, lights.0.size=0.5) or "
                     "view.image=final|shadow|moments_raw|moments_filtered|sat, view.channel=all|0-3")
        ->allow_extra_args(false);
    view->add_flag("--no-panels", a->noPanels, "the image alone, without the ImGui panel column");
    view->callback([a, &ctx] { ctx.exitCode = runView(*a); });
}

}  // namespace sl::cli
