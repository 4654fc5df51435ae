// scene_list.h: which scenes are graded, and which of them are hidden.
#pragma once

#include "scene.h"

#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace sl::grader {

// A graded scene, parsed once here: the grade, its scoring and the golden checks read `scene`.
struct GradedScene {
    std::string name;
    std::filesystem::path path;
    std::string filter;  // "gaussian" | "sat" | "none"
    bool hidden = false;  // not a scene students have (isHiddenScenePath)
    std::shared_ptr<const Scene> scene;
};

// The public scenes (scenes/*.json under the repository root) that have a shadowing light,
// sorted by name; with `only` non-empty, those names (throws std::runtime_error for an
// unknown or unshadowed one). A name may also be a path to a scene file (hidden scenes), and
// "public" stands for every public scene. A scene named twice is graded once; two different
// files with the same name (stem) are an error (their tests and goldens would collide).
std::vector<GradedScene> gradedScenes(const std::vector<std::string>& only = {});

// A scene file students do not have: outside the kit's scenes/ folder, or inside
// scenes/hidden/ (which the student kit leaves out). scenes/ and its other subfolders ship.
bool isHiddenScenePath(const std::filesystem::path& scene);

}  // namespace sl::grader
