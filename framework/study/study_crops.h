// study_crops: failure crops, how Peters & Klein show light leaking and over-darkening: for a
// study row, the window of its image where it leaks most (G below the truth: light where the
// truth has shadow) and the one where it over-darkens most (G above the truth: acne, a filter's
// bias, a moment bound), each as [G | truth | error map] side by side, enlarged. Drawn from the
// study's own files (the row's G and error PNGs, the truth's PNG), read and written through the
// image codec (OpenImageIO).
#pragma once

#include "study_table.h"

#include <filesystem>
#include <string>
#include <vector>

namespace sl {

namespace fs = std::filesystem;

struct FailureCrop {
    std::string kind;   // "leak" or "dark"
    std::string file;   // under the study folder: crops/<name>_<kind>.png
    double meanError = 0;  // mean |ΔG| of that kind over the window's reached pixels
    int x = 0, y = 0, size = 0;  // the window, pixels from the image's top left
};

// Writes DIR/crops/<name>_leak.png and _dark.png for `row` (truthPng: the truth's preview under
// DIR); a kind is left out where the row has no pixel off by more than 0.1 that way.
std::vector<FailureCrop> writeFailureCrops(const fs::path& dir, const StudyRow& row,
                                           const std::string& truthPng, const std::string& name);

}  // namespace sl
