// The GLFW window (`shadowlab view`): under a virtual X server (Xvfb) it shows the same image
// that the headless `render` writes, and without a display it says so instead of crashing.
#include "gl_test_support.h"
#include "image_io.h"

#include <unistd.h>

#include <cmath>
#include <csignal>

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

}  // namespace

TEST(Viewer, WindowShowsTheImageRenderWrites) {
    if (!haveXvfb()) GTEST_SKIP() << "Xvfb not installed (./kit installs the xvfb package)";
    VirtualDisplay display;
    fs::path dir = test::tempDir("viewer");
    const std::string scene = test::scenePath("classic").string();
    auto shot = test::runCommand("DISPLAY=:" + std::to_string(display.number) + " " +
                                 test::shadowlabBinary() + " view --scene " + scene +
                                 " --frames 2 --screenshot " + (dir / "window.png").string());
    ASSERT_EQ(shot.exitCode, 0) << shot.output;
    EXPECT_NE(shot.output.find("llvmpipe"), std::string::npos) << shot.output;
    auto render = test::runCommand(test::shadowlabBinary() + " render --scene " + scene +
                                   " --out " + (dir / "render").string());
    ASSERT_EQ(render.exitCode, 0) << render.output;
    Image window = readImage(dir / "window.png");
    Image file = readImage(dir / "render" / "final.png");
    ASSERT_EQ(window.width, file.width);
    ASSERT_EQ(window.height, file.height);
    double worst = 0.0;
    for (int y = 0; y < file.height; ++y)
        for (int x = 0; x < file.width; ++x)
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, double(std::abs(window.at(x, y, c) - file.at(x, y, c))));
    // The same float image, sRGB-encoded on the GPU (window) and on the CPU (PNG): the two
    // pow() implementations may round one 8-bit step apart.
    EXPECT_LE(worst, 1.0 / 255.0 + 1e-6);
}

TEST(Viewer, NoDisplayIsAClearError) {
    auto r = test::runCommand("env -u DISPLAY -u WAYLAND_DISPLAY " + test::shadowlabBinary() +
                              " view --scene " + test::scenePath("classic").string());
    EXPECT_EQ(r.exitCode, 4) << r.output;
    EXPECT_NE(r.output.find("no display"), std::string::npos) << r.output;
}

}  // namespace sl
