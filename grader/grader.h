// grader.h: the types the grader's files share: a grade's options, one scored test, a grade's
// summary and a batch's row of it. The concepts live in their own files, one folder per part:
// intake/ (intake, out_guard, isolation, worker, jobs, raw_image), scoring/ (stages, rubric,
// points, metrics, score_render), output/ (results, report, report_diagnosis), goldens/,
// packaging/, batch/; grade.cpp grades one submission (docs/grading.md).
#pragma once

#include "image.h"
#include "stages.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace sl::grader {

namespace fs = std::filesystem;

struct GradeOptions {
    fs::path submission;          // folder of stage files
    fs::path out;                 // results.json, report/, .work-<pid>/ (scratch)
    std::vector<std::string> scenes;  // names; empty: every public scene with a shadowing light
    std::string reference = "auto";   // live | golden | auto (live if reference/ exists)
    double timeoutSeconds = 0.0;  // 0: from the reference's own render time (jobs.h)
    long memoryMb = 4096;
    int jobs = 2;                 // workers at a time
    fs::path goldens;             // default: scenes/goldens
    fs::path rubric;              // default: grader/rubric.json
    bool report = true;           // write OUT/report
    std::string backend = "auto";
    bool keepWork = false;        // keep OUT/.work (the workers' images and logs)
    fs::path referenceImages;     // live mode: reference renders made already (batch)
    fs::path rowFile;             // batch: where gradeAndPrint writes the submission's BatchRow

    // The one encoding of the options across a process boundary (a batch's exec'd child).
    nlohmann::json toJson() const;
    static GradeOptions fromJson(const nlohmann::json& j);  // throws std::invalid_argument
};

// One Gradescope test: a (scene, stage) pair.
struct TestResult {
    std::string scene, stage;
    bool hidden = false;      // a scene given by path outside scenes/: after_due_date
    double score = 0.0, maxScore = 0.0;
    std::string output;       // reason, metrics
    nlohmann::json metrics;   // per image: fraction within tolerance, OIIO figures, NaN count
    std::vector<std::string> images;  // compared image names (report)
    double fraction = 0.0;    // the fraction of points earned (before scaling to maxScore)
    // Fewer points than the test is worth (beyond the rounding of the points' sums).
    bool lostPoints() const { return score < maxScore - 1e-9; }
    // The stage is still the stub ("not implemented: FILE: FUNCTION ..."): no diagnosis.
    bool notImplemented() const { return output.rfind("not implemented", 0) == 0; }
};

struct GradeSummary {
    double score = 0.0, maxScore = 0.0;
    std::vector<TestResult> tests;
    std::vector<std::string> warnings;  // golden manifest mismatch, skipped scenes
    double seconds = 0.0;
    std::string referenceMode;          // "live" | "golden"
    std::string filterMode = "both";    // the rubric's "filters": both | either
    std::vector<std::string> notes;     // how it was graded: filter mode, points per stage
    // What the failures look like (report_diagnosis.h), visible tests only: the report's list,
    // printed under the score table too.
    std::vector<std::string> findings;
    bool failed = false;                // the grader itself failed (results.json says why)
    std::string failure;                // then: why
};

// What scores.csv shows of one submission, handed from its grade to the batch as data.
struct BatchRow {
    bool failed = false;
    double score = 0.0, maxScore = 0.0;
    std::map<std::string, double> stagePoints;  // stage -> points earned
    std::map<std::string, double> stageMax;     // stage -> points it is worth
    std::vector<std::string> lost;               // "scene stage -points" per test short of full
    std::vector<std::string> notes;              // the visible warnings, or why it failed
    bool report = false;                         // OUT/<name>/report/index.html was written
    std::string digest;  // what was graded (batch_store.h): the submission's bytes and the setup

    nlohmann::json toJson() const;
    static BatchRow fromJson(const nlohmann::json& j);
};

// "live" or "golden" for --reference live|golden|auto (auto: live if reference/ is complete).
std::string resolveReferenceMode(const std::string& requested);

// Live mode, for many submissions: renders each scene's reference once into dir/<scene>/.
void renderReferenceImages(const GradeOptions& options, const fs::path& dir);

// Grades one submission; writes OUT/results.json (always), OUT/report/. Never throws.
GradeSummary gradeSubmission(const GradeOptions& options);

}  // namespace sl::grader
