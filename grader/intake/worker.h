// worker.h: what one grader child process renders (the hidden `grade-worker` subcommand), and
// the two things that cross the process boundary, each in one typed encoding: the arguments
// (WorkerArgs, as JSON on the exec'd command line) and the result (WorkerResult, worker.json).
#pragma once

#include "renderer.h"
#include "scene.h"
#include "stages.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sl::grader {

struct WorkerArgs {
    std::string scene;                 // scene JSON path
    const StageRow* stage = nullptr;   // the stage rendered; nullptr: the whole reference
    std::string submission;            // staged submission folder
    std::string reference;             // reference solution folder ("" when only goldens exist)
    std::string input;                 // reference moments_raw (gaussian, sat) or moments_filtered (msm)
    std::string out;                   // folder for <image>.raw and worker.json
    std::string backend = "auto";

    nlohmann::json toJson() const;
    // Throws std::invalid_argument naming the field that is missing or wrong.
    static WorkerArgs fromJson(const nlohmann::json& j);
};

// A stub note of the render: `file` is the submission's stage file it names ("" for any other
// file), so that the grader matches notes to stages by file name, not by searching the text.
struct StubNote {
    std::string file;
    std::string text;  // "submission/msm.glsl: momentShadowIntensity: not implemented yet ..."
};

inline constexpr const char* kWorkerResultFile = "worker.json";

// What a worker writes last, in OUT/<job>/worker.json.
struct WorkerResult {
    std::string stage, scene;
    bool stubEverywhere = false;      // the stage's output is the stub everywhere (grade.cpp, scouts)
    std::vector<std::string> images;  // the <image>.raw files written
    std::vector<StubNote> stubNotes;
    nlohmann::json robustness;        // the hard cases' score, counts, failing cases, summary
    std::string backend, renderer, mesaVersion;

    nlohmann::json toJson() const;
    static WorkerResult fromJson(const nlohmann::json& j);
};

// A worker's result from its folder; nullopt while it is absent or not yet whole.
std::optional<WorkerResult> readWorkerResult(const std::filesystem::path& folder);

// Renders and writes the stage's images. Throws (ShaderError for compile/link errors: the
// command line turns it into exit code 3 and the mapped log on stderr).
void runWorker(const WorkerArgs& args);

// runWorker as a process's whole work: the exit code and stderr text of `shadowlab
// grade-worker` (exit_codes.h). A child forked without exec runs this (isolation.h).
int workerMain(const WorkerArgs& args);

}  // namespace sl::grader
