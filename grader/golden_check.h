// golden_check: whether committed goldens still stand for a fresh reference render
// (`golden --check`). Pixels are compared, never file bytes: another OpenEXR or libpng writes
// the same pixels as other bytes. On the goldens' own renderer (Mesa version and GL_RENDERER,
// which names LLVM) the pixels must be identical: renders are deterministic there. On any
// other renderer each image must earn full marks under the default rubric's rule for its
// stage, the rule students are graded by: the goldens still grade a correct solution fairly.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace sl::grader {

struct GoldenVerdicts {
    std::vector<std::string> stale;  // "scene/image" or "scene/image: why"
    std::vector<std::string> notes;  // images that differ within the tolerance (other renderer)
};

// Compares scene `scene`'s fresh entry (its files in `freshDir`) with the committed
// manifest `committed` (files in `committedDir`, the scene's folder); `sameRenderer`: this
// machine's renderer is the one the goldens were made with.
void checkGoldenEntry(const std::string& scene, const nlohmann::json& fresh,
                      const std::filesystem::path& freshDir, const nlohmann::json& committed,
                      const std::filesystem::path& committedDir, bool sameRenderer,
                      GoldenVerdicts& verdicts);

// The stage whose rule an image of the goldens is compared by: moments_raw -> moments,
// moments_filtered -> gaussian (the filters share one rule), shadow images -> msm, final.
std::string goldenImageStage(const std::string& image);

}  // namespace sl::grader
