// jobs: the workers' command lines and folders, their time limits, and the reference renders
// a batch shares.
#include "jobs.h"

#include "gl_context.h"
#include "golden.h"
#include "image_io.h"
#include "raw_image.h"
#include "paths.h"
#include "shader_source.h"
#include "worker.h"

#include <unistd.h>

#include <cstdio>
#include <fstream>
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

std::vector<std::pair<std::string, std::string>> shaderCacheEnvironment(const GradeOptions& o) {
    const fs::path cache = workDir(o) / "shader-cache";
    std::error_code ec;
    fs::create_directories(cache, ec);
    if (ec) return {};  // the cache stays off
    return {{"MESA_SHADER_CACHE_DISABLE", "false"}, {"MESA_GLSL_CACHE_DISABLE", "false"},
            {"MESA_SHADER_CACHE_DIR", cache.string()}, {"MESA_GLSL_CACHE_DIR", cache.string()}};
}

ChildSpec workerSpec(const GradeOptions& o, const GradedScene& scene, const StageRow* stage,
                     const fs::path& input, const fs::path& out) {
    WorkerArgs w;
    w.scene = scene.path.string();
    w.stage = stage;
    w.submission = (workDir(o) / "submission").string();
    // Against goldens a stage never reads reference/, present or not: the student kit's
    // self-check and the full kit's `--reference golden` are one computation.
    w.reference = resolveReferenceMode(o.reference) == "live" ? (repoRoot() / "reference").string() : "";
    w.input = input.string();
    w.out = out.string();
    w.backend = o.backend;
    ChildSpec spec;
    // Forked, the child runs workerMain(w); exec'd, the same arguments cross as JSON.
    spec.args = {"--backend", o.backend, "grade-worker", "--job", w.toJson().dump()};
    spec.run = [w] { return workerMain(w); };
    spec.logPath = out / "log.txt";
    // A stage's renders compile its files only: once one loops, the others would too. A final
    // compiles every file of its scene, so its own timeout names none of them and stops no
    // other render (a final skips on its stages' groups: alsoRuns).
    spec.group = !stage ? "reference" : stage->stage == Stage::Final ? "" : stage->name;
    spec.env = shaderCacheEnvironment(o);
    // Most specific first: the staged copies, then OUT, then the kit and the scene's folder.
    auto dir = [](const fs::path& p) {
        std::error_code ec;
        const fs::path c = fs::weakly_canonical(p, ec);
        return (ec ? p : c).string() + "/";
    };
    spec.scrub = {{dir(workDir(o) / "submission"), "submission/"},
                  {dir(o.out), ""},
                  {dir(repoRoot()), ""},
                  {dir(scene.path.parent_path()), ""}};
    return spec;
}

double stageTimeout(const GradeOptions& o, double referenceSeconds) {
    if (o.timeoutSeconds > 0) return o.timeoutSeconds;
    if (referenceSeconds > 0) return std::max(kTimeoutFloor, kTimeoutFactor * referenceSeconds);
    return kTimeoutDefault;
}

std::string timeoutNote(const GradeOptions& o, double referenceSeconds) {
    if (o.timeoutSeconds > 0) return " (--timeout)";
    if (referenceSeconds <= 0) return "";
    char buf[96];
    std::snprintf(buf, sizeof buf, " (%g x the reference's %.2f s render%s)", kTimeoutFactor,
                  referenceSeconds, kTimeoutFactor * referenceSeconds < kTimeoutFloor ? ", at least 5 s" : "");
    return buf;
}

double referenceTimeout(const GradeOptions& o) {
    return o.timeoutSeconds > 0 ? 4 * o.timeoutSeconds : 120.0;
}

std::map<std::string, double> readReferenceTimes(const fs::path& dir) {
    std::map<std::string, double> times;
    if (dir.empty()) return times;
    std::ifstream in(dir / "times.json");
    const auto j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_object())
        for (const auto& [name, v] : j.items())
            if (v.is_number()) times[name] = v.get<double>();
    return times;
}

void decodeGoldens(const GradeOptions& o, const std::vector<GradedScene>& scenes, const fs::path& goldens) {
    std::vector<ChildSpec> specs;
    for (const auto& scene : scenes) {
        const fs::path from = goldenFolder(scene, goldens) / scene.name;
        const fs::path to = workDir(o) / "golden" / scene.name;
        fs::create_directories(to);
        ChildSpec spec;
        spec.logPath = to / "log.txt";
        spec.run = [from, to] {
            std::error_code ec;
            for (const auto& f : fs::directory_iterator(from, ec)) {
                if (f.path().extension() != ".exr") continue;
                const fs::path raw = to / (f.path().stem().string() + ".raw");
                try {
                    writeRaw(readAnyImage(f.path()), raw.string() + ".part");
                    fs::rename(raw.string() + ".part", raw);
                } catch (const std::exception&) {
                }
            }
            return 0;
        };
        specs.push_back(spec);
    }
    runChildren(specs, {kTimeoutDefault, o.memoryMb}, o.jobs);
}

std::string resolveReferenceMode(const std::string& requested) {
    if (requested == "auto") return haveReference() ? "live" : "golden";
    return requested;
}

void renderReferenceImages(const GradeOptions& o, const fs::path& dir) {
    if (!haveReference()) throw std::runtime_error("live reference renders need reference/");
    std::vector<ChildSpec> specs;
    const auto scenes = gradedScenes(o.scenes);
    for (const auto& scene : scenes) {
        fs::create_directories(dir / scene.name);
        specs.push_back(workerSpec(o, scene, nullptr, "", dir / scene.name));
        specs.back().group.clear();
    }
    nlohmann::json times = nlohmann::json::object();
    preloadDriver(parseBackendKind(o.backend));  // once here, not in every forked child
    const auto results = runChildren(specs, {referenceTimeout(o), o.memoryMb, true}, o.jobs);
    std::error_code ec;
    fs::remove_all(workDir(o), ec);  // the shader cache of these renders
    fs::remove(o.out, ec);           // the batch's scratch folder, if nothing else is there
    for (size_t i = 0; i < results.size(); ++i) {
        const auto& r = results[i];
        if (!(r.kind == ChildResult::Exited && r.exitCode == 0))
            throw std::runtime_error("a reference render failed:\n" + r.log);
        times[scenes[i].name] = r.seconds;
    }
    std::ofstream(dir / "times.json") << times.dump(2) << "\n";
}

}  // namespace sl::grader
