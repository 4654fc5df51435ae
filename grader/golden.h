// golden.h: golden images — the reference renders shipped for grading without reference/.
#pragma once

#include "image.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace sl::grader {

namespace fs = std::filesystem;

struct GoldenOptions {
    std::string solution = "reference";
    fs::path out;                      // e.g. scenes/goldens
    std::vector<std::string> scenes;   // empty: every graded public scene
    std::string backend = "auto";
    bool check = false;  // render, encode, and compare hashes with out/manifest.json instead
};

// Renders every scene through the solution in this process and writes, per scene,
// <scene>/<image>.exr (moments float32 with a shortened mantissa, images half; ZIP) and
// out/manifest.json. With `check`, writes nothing and returns the images whose encoding
// differs from the manifest's hash (empty: the goldens are up to date).
std::vector<std::string> makeGoldens(const GoldenOptions& options);

// Reads one golden image ("" if absent).
Image readGolden(const fs::path& goldens, const std::string& scene, const std::string& image);
nlohmann::json readManifest(const fs::path& goldens);  // null if absent

// Messages for each way the running renderer differs from the manifest's.
std::vector<std::string> manifestWarnings(const nlohmann::json& manifest,
                                          const nlohmann::json& running);

}  // namespace sl::grader
