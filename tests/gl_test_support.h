// gl_test_support: what the GPU tests share — one GL context per test process, the repo's
// folders, rendering a scene through a solution, and running the shadowlab binary.
#pragma once

#include "gl_context.h"
#include "image_io.h"
#include "pass_plan.h"
#include "paths.h"
#include "renderer.h"
#include "scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

namespace sl::test {

inline GlContext& sharedContext() {
    static std::unique_ptr<GlContext> context = createContext(BackendKind::Auto);
    context->activate();  // another test may have made its own context current
    return *context;
}

// The backend `auto` takes here: OSMesa where libOSMesa loads (Debian 12, 13), else EGL (Mesa
// 25.1 and later have no OSMesa).
inline std::string autoBackend() { return whyNoOSMesa().empty() ? "osmesa" : "egl"; }

// A check of the OSMesa backend on a machine without it is skipped, with the reason.
#define SL_SKIP_WITHOUT_OSMESA()                                                  \
    if (const std::string why = ::sl::whyNoOSMesa(); !why.empty())                \
        GTEST_SKIP() << "no OSMesa backend here: " << why

inline fs::path root() { return repoRoot(); }
inline fs::path scenePath(const std::string& name) { return root() / "scenes" / (name + ".json"); }

// A file's bytes as they are (text or binary).
inline std::string readFile(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The rows of a CSV file (plain commas, no quoting: what `shadowlab probe` writes), each a list
// of fields; none if the file is missing.
inline std::vector<std::vector<std::string>> readCsv(const fs::path& p) {
    std::ifstream in(p);
    std::vector<std::vector<std::string>> rows;
    std::string line;
    while (std::getline(in, line)) {
        std::vector<std::string> fields;
        std::stringstream ss(line);
        std::string f;
        while (std::getline(ss, f, ',')) fields.push_back(f);
        rows.push_back(fields);
    }
    return rows;
}

// Writes `text` to `p`, replacing the file; its folder is made if missing.
inline void writeFile(const fs::path& p, const std::string& text) {
    if (p.has_parent_path()) fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
}

inline ShaderLibrary library(const std::string& solution) {
    return ShaderLibrary::forSolution(resolveSolution(solution), root());
}

// Every image the scene can make (a SAT scene's filtered map too).
inline RenderResult renderScene(const Scene& scene, const std::string& solution = "reference") {
    sharedContext();
    Renderer renderer(library(solution));
    return renderer.render(scene, planPasses(scene, {.resolveSat = true}));
}

// A fresh, empty folder for one test's files.
inline fs::path tempDir(const std::string& name) {
    const char* base = std::getenv("SHADOWLAB_TEST_TMP");
    fs::path dir = fs::path(base ? base : "/tmp/shadowlab-tests") / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

struct CommandResult {
    int exitCode = -1;
    std::string output;  // stdout and stderr together
};

// Runs `command` through the shell (the tests' own fixed command lines only).
inline CommandResult runCommand(const std::string& command) {
    CommandResult r;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return r;
    char buf[4096];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, pipe)) > 0) r.output.append(buf, n);
    int status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

// Opens `page` in headless Chromium and saves a `width`×`height` screenshot as `shot`. The
// flags are what this machine needs: no sandbox (root), and no background networking on a
// closed network. Callers check `command -v chromium` first and skip without it.
inline CommandResult screenshotPage(const fs::path& page, const fs::path& shot,
                                    const fs::path& profile, int width, int height) {
    return runCommand(
        "timeout 60 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
        "--disable-background-networking --disable-component-update --disable-sync "
        "--user-data-dir=" + profile.string() + " --window-size=" + std::to_string(width) + "," +
        std::to_string(height) + " --screenshot=" + shot.string() + " file://" +
        fs::absolute(page).string());
}

// The sum over R, G, B of each channel's standard deviation: about 0 for a blank (one-colour)
// screenshot.
inline double colourSpread(const fs::path& png) {
    const Image img = readImage(png);
    double spread = 0;
    const size_t n = size_t(img.width) * img.height;
    for (int c = 0; c < 3 && c < img.channels; ++c) {
        double sum = 0, sum2 = 0;
        for (size_t i = 0; i < n; ++i) {
            const double v = img.pixels[i * img.channels + c];
            sum += v;
            sum2 += v * v;
        }
        const double mean = sum / double(n);
        spread += std::sqrt(std::max(0.0, sum2 / double(n) - mean * mean));
    }
    return spread;
}

// build/shadowlab, next to this test binary's folder (build/tests/); found at run time so that
// no path is compiled in (ccache shares the objects between copies of the kit).
inline std::string shadowlabBinary() {
    return (fs::read_symlink("/proc/self/exe").parent_path().parent_path() / "shadowlab").string();
}

}  // namespace sl::test
