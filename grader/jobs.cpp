// jobs: the workers' command lines and folders, and the reference renders a batch shares.
#include "jobs.h"

#include "paths.h"
#include "shader_source.h"

#include <unistd.h>

#include <stdexcept>

namespace sl::grader {

fs::path workDir(const GradeOptions& o) {
    return o.out / (".work-" + std::to_string(::getpid()));
}

bool haveReference() {
    for (const auto& f : stageFileNames())
        if (!fs::exists(repoRoot() / "reference" / f)) return false;
    return true;
}

ChildSpec workerSpec(const GradeOptions& o, const GradedScene& scene, const std::string& stage,
                     const fs::path& input, const fs::path& out) {
    std::vector<std::string> args = {"--backend", o.backend, "grade-worker",
                                     "--scene", scene.path.string(),
                                     "--stage", stage,
                                     "--submission", (workDir(o) / "submission").string(),
                                     "--input", input.string(),
                                     "--out", out.string()};
    if (haveReference()) args.insert(args.end(), {"--reference", (repoRoot() / "reference").string()});
    return {args, out / "log.txt"};
}

std::string resolveReferenceMode(const std::string& requested) {
    if (requested == "auto") return haveReference() ? "live" : "golden";
    return requested;
}

void renderReferenceImages(const GradeOptions& o, const fs::path& dir) {
    if (!haveReference()) throw std::runtime_error("live reference renders need reference/");
    std::vector<ChildSpec> specs;
    for (const auto& scene : gradedScenes(o.scenes)) {
        fs::create_directories(dir / scene.name);
        specs.push_back(workerSpec(o, scene, "reference", "", dir / scene.name));
    }
    for (const auto& r : runChildren(specs, {o.timeoutSeconds * 4, o.memoryMb}, o.jobs))
        if (!(r.kind == ChildResult::Exited && r.exitCode == 0))
            throw std::runtime_error("a reference render failed:\n" + r.log);
}

}  // namespace sl::grader
