// The GLFW window (`shadowlab view`): under a virtual X server (Xvfb) it shows the same image
// that the headless `render` writes, draws its Dear ImGui panel beside the image, applies a
// scripted setting (--set, one per frame, as the panel does) by re-planning and re-rendering
// to exactly what `render` makes of the same setting written in the scene file; and without
// a display, or with a bad setting, it says so instead of crashing.
#include "gl_test_support.h"
#include "image_io.h"

#include <imgui.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <fstream>

namespace sl {
namespace {

// An Xvfb server on a display number of its own for the test's lifetime.
struct VirtualDisplay {
    int number = 0;
    pid_t pid = -1;
    VirtualDisplay() {
        number = 100 + int(getpid() % 400);
        pid = fork();
        if (pid == 0) {
            const std::string d = ":" + std::to_string(number);
            execlp("Xvfb", "Xvfb", d.c_str(), "-screen", "0", "1024x768x24", "-nolisten", "tcp",
                   static_cast<char*>(nullptr));
            _exit(127);
        }
        for (int i = 0; i < 50 && !fs::exists("/tmp/.X11-unix/X" + std::to_string(number)); ++i)
            usleep(100000);
    }
    ~VirtualDisplay() {
        if (pid > 0) kill(pid, SIGTERM);
    }
};

bool haveXvfb() { return test::runCommand("command -v Xvfb").exitCode == 0; }

// `shadowlab view` on the display with `args`, screenshot of its last frame in `png`.
Image viewShot(const VirtualDisplay& display, const std::string& args, const fs::path& png) {
    auto r = test::runCommand("DISPLAY=:" + std::to_string(display.number) + " " +
                              test::shadowlabBinary() + " view " + args + " --screenshot " +
                              png.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("llvmpipe"), std::string::npos) << r.output;
    return r.exitCode == 0 ? readImage(png) : Image();
}

Image renderPng(const std::string& scene, const fs::path& out, const std::string& name) {
    auto r = test::runCommand(test::shadowlabBinary() + " render --scene " + scene + " --out " +
                              out.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return readImage(out / (name + ".png"));
}

// Largest difference between `file` and the window's top-left file-sized corner (the image
// sits there, the panel to its right), over RGB; `fileChannel` >= 0 compares every window
// channel to that one channel of the file (a channel shown as grey). Images are bottom row
// first in memory, so the window's top rows are its last ones.
double worstInImageCorner(const Image& window, const Image& file, int fileChannel = -1) {
    if (window.width < file.width || window.height < file.height) return 1e9;
    const int dy = window.height - file.height;
    double worst = 0.0;
    for (int y = 0; y < file.height; ++y)
        for (int x = 0; x < file.width; ++x)
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, double(std::abs(window.at(x, y + dy, c) -
                                                        file.at(x, y, fileChannel >= 0 ? fileChannel
                                                                      : std::min(c, file.channels - 1)))));
    return worst;
}

// Every 2×2 block averaged: what bilinear sampling between the four texels gives when the
// window shows a map at half its size (a 1024² moment map in a 512² image area).
Image halved(const Image& image) {
    Image out(image.width / 2, image.height / 2, image.channels);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x)
            for (int c = 0; c < image.channels; ++c)
                out.at(x, y, c) = 0.25f * (image.at(2 * x, 2 * y, c) + image.at(2 * x + 1, 2 * y, c) +
                                           image.at(2 * x, 2 * y + 1, c) + image.at(2 * x + 1, 2 * y + 1, c));
    return out;
}

// The same float image, sRGB-encoded on the GPU (window) and on the CPU (PNG): the two pow()
// implementations may round one 8-bit step apart.
constexpr double kOneStep = 1.0 / 255.0 + 1e-6;

}  // namespace

TEST(Viewer, WindowShowsTheImageRenderWrites) {
    if (!haveXvfb()) GTEST_SKIP() << "Xvfb not installed (./kit installs the xvfb package)";
    VirtualDisplay display;
    fs::path dir = test::tempDir("viewer");
    const std::string scene = test::scenePath("classic").string();
    // --screenshot alone ends the run (no --frames), into a folder it makes.
    Image window = viewShot(display, "--scene " + scene + " --no-panels", dir / "new/window.png");
    Image file = renderPng(scene, dir / "render", "final");
    ASSERT_EQ(window.width, file.width);  // --no-panels: the image alone
    ASSERT_EQ(window.height, file.height);
    EXPECT_LE(worstInImageCorner(window, file), kOneStep);
}

TEST(Viewer, PanelDrawsBesideTheImage) {
    if (!haveXvfb()) GTEST_SKIP() << "Xvfb not installed (./kit installs the xvfb package)";
    VirtualDisplay display;
    fs::path dir = test::tempDir("viewer_panel");
    const std::string scene = test::scenePath("classic").string();
    Image window = viewShot(display, "--scene " + scene + " --frames 3", dir / "window.png");
    Image file = renderPng(scene, dir / "render", "final");
    ASSERT_GT(window.width, file.width + 200) << "no room for the panel";
    EXPECT_LE(worstInImageCorner(window, file), kOneStep) << "the panel covers the image";

    // ImGui's dark style paints its windows' background WindowBg (alpha 0.94) over the
    // black the viewer clears to: expected 8-bit value c8 · a8 / 255 from ImGui's own table.
    ImGui::CreateContext();
    ImGui::StyleColorsDark();
    const ImU32 bg = ImGui::ColorConvertFloat4ToU32(ImGui::GetStyle().Colors[ImGuiCol_WindowBg]);
    ImGui::DestroyContext();
    const double alpha = double((bg >> IM_COL32_A_SHIFT) & 0xFF) / 255.0;
    const double expected[3] = {double((bg >> IM_COL32_R_SHIFT) & 0xFF) * alpha / 255.0,
                                double((bg >> IM_COL32_G_SHIFT) & 0xFF) * alpha / 255.0,
                                double((bg >> IM_COL32_B_SHIFT) & 0xFF) * alpha / 255.0};
    long background = 0, bright = 0, column = 0;
    for (int y = 0; y < window.height; ++y)
        for (int x = file.width + 8; x < window.width - 8; ++x, ++column) {
            bool isBg = true, isBright = true;
            for (int c = 0; c < 3; ++c) {
                isBg = isBg && std::abs(window.at(x, y, c) - expected[c]) <= 1.5 / 255.0;
                isBright = isBright && window.at(x, y, c) > 0.8f;
            }
            background += isBg;
            bright += isBright;
        }
    // A panel drawn nowhere (e.g. ImGui's GL calls going to no context) leaves the column
    // black; one drawn over the image fails the corner check above.
    EXPECT_GT(background, column / 4) << "ImGui's window background is missing";
    EXPECT_GT(bright, 300) << "no text in the panel";
}

TEST(Viewer, ScriptedTechniqueAndFilterReplanToWhatTheSceneFileWouldRender) {
    if (!haveXvfb()) GTEST_SKIP() << "Xvfb not installed (./kit installs the xvfb package)";
    VirtualDisplay display;
    fs::path dir = test::tempDir("viewer_settings");
    const std::string scene = test::scenePath("classic").string();
    // The same changes, written into a copy of the scene file and rendered headless.
    nlohmann::json json;
    std::ifstream(scene) >> json;
    json["shadow"]["technique"] = "vsm";
    json["shadow"]["filter"] = {{"type", "sat"}, {"kernel", 25}};
    std::ofstream(dir / "classic_vsm_sat.json") << json.dump(2);
    Image expected = renderPng((dir / "classic_vsm_sat.json").string(), dir / "render", "final");
    Image before = renderPng(scene, dir / "render_before", "final");

    auto r = test::runCommand("DISPLAY=:" + std::to_string(display.number) + " " +
                              test::shadowlabBinary() + " view --scene " + scene +
                              " --set shadow.technique=vsm --set shadow.filter.type=sat"
                              " --set shadow.filter.kernel=25 --frames 4 --screenshot " +
                              (dir / "window.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // Each edit re-planned, one "plan" line each: the technique first (classic's Gaussian
    // stays, VSM takes one), then the SAT passes in place of the Gaussian ones.
    std::vector<std::string> plans;
    for (size_t at = r.output.find("plan ("); at != std::string::npos; at = r.output.find("plan (", at + 1))
        plans.push_back(r.output.substr(at, r.output.find('\n', at) - at));
    ASSERT_EQ(plans.size(), 3u) << r.output;
    EXPECT_NE(plans[0].find("(vsm, gaussian): shadow gaussian-x gaussian-y"), std::string::npos) << plans[0];
    EXPECT_NE(plans[2].find("(vsm, sat): shadow sat-rows sat-columns"), std::string::npos) << plans[2];
    Image window = readImage(dir / "window.png");
    EXPECT_LE(worstInImageCorner(window, expected), kOneStep);
    // ... and the change shows: VSM over a 25-texel box is not MSM over a radius-4 Gaussian.
    long changed = 0;
    const int dy = window.height - before.height;
    for (int y = 0; y < before.height; ++y)
        for (int x = 0; x < before.width; ++x)
            changed += std::abs(window.at(x, y + dy, 0) - before.at(x, y, 0)) > 4.0f / 255.0f;
    EXPECT_GT(changed, 2000);
}

TEST(Viewer, ScriptedImageAndChannelShowWhatRenderWrites) {
    if (!haveXvfb()) GTEST_SKIP() << "Xvfb not installed (./kit installs the xvfb package)";
    VirtualDisplay display;
    fs::path dir = test::tempDir("viewer_images");
    const std::string scene = test::scenePath("classic").string();
    renderPng(scene, dir / "render", "final");
    Image shadow = viewShot(display, "--scene " + scene + " --set view.image=shadow --frames 2",
                            dir / "shadow.png");
    EXPECT_LE(worstInImageCorner(shadow, readImage(dir / "render" / "shadow.png")), kOneStep);
    // Channel 1 (z²) of the raw moments, as grey: the PNG preview's green channel, the
    // 1024² map fitted into the 512² image area. (Averages of 8-bit PNG texels and the 8-bit
    // average of float texels differ by at most one step.)
    Image z2 = viewShot(display, "--scene " + scene +
                        " --set view.image=moments_raw --set view.channel=1 --frames 3",
                        dir / "z2.png");
    Image moments = readImage(dir / "render" / "moments_raw.png");
    ASSERT_EQ(moments.width, 1024);
    EXPECT_LE(worstInImageCorner(z2, halved(moments), 1), 1.5 / 255.0);
}

TEST(Viewer, BadSettingIsAClearErrorBeforeAnyWindow) {
    // No display needed: every --set is checked before the window opens.
    const std::string view = "env -u DISPLAY -u WAYLAND_DISPLAY " + test::shadowlabBinary() +
                             " view --scene " + test::scenePath("classic").string();
    auto r = test::runCommand(view + " --set shadow.filter.radius=100");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--set shadow.filter.radius=100: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("classic.json: /shadow/filter/radius: expected an integer in [0, 64]"),
              std::string::npos) << r.output;
    r = test::runCommand(view + " --set view.image=nope");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("view.image=nope: expected one of final"), std::string::npos) << r.output;
    r = test::runCommand(view + " --set radius");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("expected key=value"), std::string::npos) << r.output;
    r = test::runCommand(view + " --set shadow.filter.radius=8 --frames 1");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("expected more frames than --set edits"), std::string::npos) << r.output;
}

TEST(Viewer, NoDisplayIsAClearError) {
    auto r = test::runCommand("env -u DISPLAY -u WAYLAND_DISPLAY " + test::shadowlabBinary() +
                              " view --scene " + test::scenePath("classic").string());
    EXPECT_EQ(r.exitCode, 4) << r.output;
    EXPECT_NE(r.output.find("no display"), std::string::npos) << r.output;
}

}  // namespace sl
