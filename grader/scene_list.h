// scene_list.h: which scenes are graded.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace sl::grader {

struct GradedScene {
    std::string name;
    std::filesystem::path path;
    std::string filter;  // "gaussian" | "sat" | "none"
    bool hidden = false;  // given by path, not one of scenes/*.json
};

// The public scenes (scenes/*.json under the repository root) that have a shadowing light,
// sorted by name; with `only` non-empty, those names (throws std::runtime_error for an
// unknown or unshadowed one). A name may also be a path to a scene file (hidden scenes), and
// "public" stands for every public scene.
std::vector<GradedScene> gradedScenes(const std::vector<std::string>& only = {});

}  // namespace sl::grader
