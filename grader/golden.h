// golden.h: golden images — the reference renders shipped for grading without reference/.
// Public scenes' goldens live in one folder (scenes/goldens, shipped in the student kit);
// a hidden scene's goldens live in a goldens/ folder next to its scene file (for the kit's
// scenes/hidden/*.json: scenes/hidden/goldens, which the student kit leaves out).
#pragma once

#include "image.h"
#include "scene_list.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace sl::grader {

namespace fs = std::filesystem;

struct GoldenOptions {
    std::string solution = "reference";
    fs::path out;                      // public goldens, e.g. scenes/goldens
    std::vector<std::string> scenes;   // empty: every graded public scene
    std::string backend = "auto";
    bool check = false;  // render, encode, and compare pixels with the goldens instead
};

struct GoldenRun {
    std::vector<std::string> stale;     // check: "scene/image" (or "scene: why") that differ
    std::vector<std::string> messages;  // for the terminal: folders written, entries kept, leaks,
                                        // images within tolerance on another renderer
    std::string advice;                 // check with stale goldens: the command that remakes them
};

// Renders every scene through the solution in this process, checks each scene's probes on
// that render (a probe that does not hold throws SceneError naming the scene file, the probe
// and the values; nothing is written), and writes, per scene, <folder>/<scene>/<image>.exr
// (moments float32 with a shortened mantissa, images half; ZIP), beside each its PNG preview
// <image>.png (at most 512 wide; colour sRGB), and <folder>/manifest.json (the SHA-256 of
// both files and of their pixels, and the Mesa, LLVM and OpenImageIO versions). `check`
// compares pixels (golden_check.h): identical on the goldens' renderer, within the grading
// tolerance on another.
// A manifest is merged: entries of scenes not rendered this time are kept (and listed in
// `messages`), never dropped. With `check`, writes nothing and lists what differs.
GoldenRun runGoldens(const GoldenOptions& options);
std::vector<std::string> makeGoldens(const GoldenOptions& options);  // runGoldens(...).stale

// The folder that holds a scene's goldens: `publicGoldens` for a public scene, else
// goldens/ next to the hidden scene's file.
fs::path goldenFolder(const GradedScene& scene, const fs::path& publicGoldens);

// Checks every scene's probes on the reference images it is graded against (`file(i, image)`:
// the reference's `image` of scenes[i], a .raw or .exr; scenes whose shadow images are
// missing are skipped: their reference render failed, which is reported elsewhere). Throws
// std::runtime_error listing the probes that do not hold; a hidden scene's are not spelled
// out (the message reaches students): golden --check --scenes <file> shows them.
void checkReferenceProbes(const std::vector<GradedScene>& scenes,
                          const std::function<fs::path(size_t, const std::string&)>& file);

// Reads one golden image ("" if absent).
Image readGolden(const fs::path& goldens, const std::string& scene, const std::string& image);
nlohmann::json readManifest(const fs::path& goldens);  // null if absent

// Messages for each way the running renderer differs from the manifest's.
std::vector<std::string> manifestWarnings(const nlohmann::json& manifest,
                                          const nlohmann::json& running);

}  // namespace sl::grader
