// test_grader_support: what the grader tests share — making submissions from the reference
// with some files replaced, running `shadowlab grade`, and reading its results.json.
#pragma once

#include "gl_test_support.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <map>
#include <sstream>

namespace sl::test {

// A submission folder: the reference's five files, with `replace` (file -> text) written over
// them and the files in `drop` left out.
inline fs::path makeSubmission(const std::string& name,
                               const std::map<std::string, std::string>& replace = {},
                               const std::vector<std::string>& drop = {}) {
    fs::path dir = tempDir("grader_sub_" + name);
    for (const char* f : {"moments.glsl", "gaussian_blur.comp", "sat.comp", "sat_lookup.glsl",
                          "msm.glsl"}) {
        if (std::find(drop.begin(), drop.end(), f) != drop.end()) continue;
        auto it = replace.find(f);
        std::ofstream(dir / f) << (it != replace.end() ? it->second
                                                        : readFile(root() / "reference" / f));
    }
    return dir;
}

struct Graded {
    CommandResult run;
    nlohmann::json results;
    // Scores and outputs per "scene: stage".
    double score(const std::string& scene, const std::string& stage) const {
        for (const auto& t : results["tests"])
            if (t["name"] == scene + ": " + stage) return t["score"].get<double>();
        return -1.0;
    }
    double maxScore(const std::string& scene, const std::string& stage) const {
        for (const auto& t : results["tests"])
            if (t["name"] == scene + ": " + stage) return t["max_score"].get<double>();
        return -1.0;
    }
    std::string output(const std::string& scene, const std::string& stage) const {
        for (const auto& t : results["tests"])
            if (t["name"] == scene + ": " + stage) return t["output"].get<std::string>();
        return "";
    }
    bool full(const std::string& scene, const std::string& stage) const {
        return maxScore(scene, stage) > 0 && score(scene, stage) == maxScore(scene, stage);
    }
};

inline Graded grade(const std::string& args, const fs::path& out, const std::string& env = "") {
    Graded g;
    g.run = runCommand(env + (env.empty() ? "" : " ") + shadowlabBinary() + " grade " + args +
                       " --out " + out.string());
    std::ifstream in(out / "results.json");
    if (in) g.results = nlohmann::json::parse(in, nullptr, false);
    return g;
}

// What grade() gives, for several submissions graded by one `shadowlab grade --batch` (the
// reference renders once for all of them, two submissions at a time): per name, its
// results.json, and as `run` its own output (OUT/<name>.log: the score table, the warnings)
// followed by the batch's, with the exit code `grade --submission` would have given (the
// batch's if that failed, else 1 for a results.json without tests: the grader failed).
inline std::map<std::string, Graded> gradeBatch(const std::map<std::string, fs::path>& submissions,
                                                const std::string& args, const fs::path& out) {
    const fs::path batch = tempDir(out.filename().string() + "_batch");
    for (const auto& [name, folder] : submissions) fs::copy(folder, batch / name);
    const CommandResult run = runCommand(shadowlabBinary() + " grade --batch " + batch.string() +
                                         " -j 2 " + args + " --out " + out.string());
    std::map<std::string, Graded> graded;
    for (const auto& [name, folder] : submissions) {
        Graded& g = graded[name];
        std::ifstream in(out / name / "results.json");
        if (in) g.results = nlohmann::json::parse(in, nullptr, false);
        const bool tests = g.results.is_object() && g.results.contains("tests") &&
                           !g.results["tests"].empty();
        g.run = {run.exitCode != 0 ? run.exitCode : tests ? 0 : 1,
                 readFile(out / (name + ".log")) + run.output};
    }
    return graded;
}

}  // namespace sl::test
