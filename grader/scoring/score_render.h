// score_render: one finished stage render turned into its test. A render that did not finish
// says why (a file not submitted, a stub, a timeout, a crash, a compile error); one that did
// has each of its images compared with the reference's under the rubric's tolerance for its
// stage, and earns the points of the rubric's ramp (docs/grading.md, "Metrics").
#pragma once

#include "grader.h"
#include "isolation.h"
#include "report.h"
#include "rubric.h"
#include "scene_list.h"

#include <filesystem>
#include <functional>
#include <string>

namespace sl::grader {

// What scoring needs to know about one stage render.
struct RenderToScore {
    const StageRow& stage;
    const GradedScene& scene;           // the scene rendered (robustness: any; not named)
    std::filesystem::path out;          // the worker's folder: worker.json, <image>.raw
    std::string missing;                // "file: reason" when a file it needs was not taken
    const ChildResult& child;           // how the worker ended
    std::string notRunReason;           // not rendered: a scout showed the stage a stub
};

// The test's scene as results.json names it: the scene's name, "hard cases" for robustness.
// A reference render (stage nullptr) is named by its scene.
std::string testScene(const StageRow* stage, const GradedScene& scene);

// The test of a finished render. `referenceFile(image)` is the reference's image that
// `image` is compared with; `report` (may be null) gets each compared image, and `findings`
// (may be null) where each one's failing texels lie (report_diagnosis.h).
TestResult scoreRender(const RenderToScore& render, const GradeOptions& options, const Rubric& rubric,
                       const std::function<std::filesystem::path(const std::string& image)>& referenceFile,
                       ReportWriter* report, std::vector<ImageFindings>* findings = nullptr);

// What a worker's failure (timeout, signal, compile error, exit code) means for the student.
std::string failureText(const ChildResult& child, const GradeOptions& options);

}  // namespace sl::grader
