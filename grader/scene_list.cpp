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

namespace fs = std::filesystem;

bool loadGraded(const fs::path& path, GradedScene& out) {
    auto scene = std::make_shared<const Scene>(loadScene(path.string()));
    if (planPasses(*scene).shadowLights.empty()) return false;
    out = {scene->name, path, toString(scene->shadow.filter), false, scene};
    return true;
}

bool inside(const fs::path& file, const fs::path& dir) {
    const fs::path rel = fs::weakly_canonical(file).lexically_relative(fs::weakly_canonical(dir));
    return !rel.empty() && *rel.begin() != "..";
}

}  // namespace

bool isHiddenScenePath(const fs::path& scene) {
    const fs::path scenes = repoRoot() / "scenes";
    return !inside(scene, scenes) || inside(scene, scenes / "hidden");
}

std::vector<GradedScene> gradedScenes(const std::vector<std::string>& only) {
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
    auto add = [&out](const GradedScene& g) {
        for (const auto& o : out) {
            if (o.name != g.name) continue;
            if (fs::weakly_canonical(o.path) == fs::weakly_canonical(g.path)) return;  // twice
            throw std::runtime_error("two scenes are named \"" + g.name + "\": " + o.path.string() +
                                     " and " + g.path.string() + " (rename one: a scene's name "
                                     "is its file name, and names its tests and goldens)");
        }
        out.push_back(g);
    };
    for (const std::string& name : only) {
        if (name == "public") {  // every public scene, next to hidden ones given by path
            for (const auto& g : gradedScenes()) add(g);
            continue;
        }
        fs::path p = name.find('/') != std::string::npos || name.ends_with(".json")
                         ? fs::path(name)
                         : dir / (name + ".json");
        if (!fs::exists(p)) throw std::runtime_error("unknown scene \"" + name + "\"");
        GradedScene g;
        if (!loadGraded(p, g))
            throw std::runtime_error("scene \"" + name + "\" has no shadowing light to grade");
        g.hidden = isHiddenScenePath(p);
        add(g);
    }
    return out;
}

}  // namespace sl::grader
