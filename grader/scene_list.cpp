// scene_list: the graded scenes. A scene with no shadowing light has no moments, filter or
// shadow image to grade, so it is left out (its final image is lighting only).
#include "scene_list.h"

#include "pass_plan.h"
#include "paths.h"
#include "scene.h"

#include <algorithm>
#include <stdexcept>

namespace sl::grader {
namespace {

bool loadGraded(const std::filesystem::path& path, GradedScene& out) {
    Scene scene = loadScene(path.string());
    if (planPasses(scene).shadowLights.empty()) return false;
    out = {scene.name, path, toString(scene.shadow.filter)};
    return true;
}

}  // namespace

std::vector<GradedScene> gradedScenes(const std::vector<std::string>& only) {
    namespace fs = std::filesystem;
    std::vector<GradedScene> out;
    const fs::path dir = repoRoot() / "scenes";
    if (only.empty()) {
        std::vector<fs::path> files;
        for (const auto& e : fs::directory_iterator(dir))
            if (e.path().extension() == ".json") files.push_back(e.path());
        std::sort(files.begin(), files.end());
        for (const auto& f : files) {
            GradedScene g;
            if (loadGraded(f, g)) out.push_back(g);
        }
        return out;
    }
    for (const std::string& name : only) {
        if (name == "public") {  // every public scene, next to hidden ones given by path
            auto all = gradedScenes();
            out.insert(out.end(), all.begin(), all.end());
            continue;
        }
        fs::path p = name.find('/') != std::string::npos || name.ends_with(".json")
                         ? fs::path(name)
                         : dir / (name + ".json");
        if (!fs::exists(p)) throw std::runtime_error("unknown scene \"" + name + "\"");
        GradedScene g;
        if (!loadGraded(p, g))
            throw std::runtime_error("scene \"" + name + "\" has no shadowing light to grade");
        g.hidden = fs::weakly_canonical(p).parent_path() != fs::weakly_canonical(dir);
        out.push_back(g);
    }
    return out;
}

}  // namespace sl::grader
