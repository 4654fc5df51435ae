// stages.h: the graded stages as one table. A row says everything the grade, the worker, the
// scoring and the rubric need to know about a stage: its name (results.json's tag, rubric.json's
// key, the worker's --stage), the submission files it compiles, the reference image it renders
// from, the image it is compared on, which scenes it applies to and how it is compared. Adding
// a stage is a row here, its render in worker.cpp and its key in rubric.json (docs/grading.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "image_name.h"

namespace sl::grader {

enum class Stage { Moments, Gaussian, Sat, Msm, Robustness, Final };

// How a stage's images are compared (score_render.cpp): texel by texel on moments (the moments
// stage's tolerance, or the filter stages'), or by the 3x3 Hausdorff test on G or on colour.
enum class CompareBy { Moments, Filtered, Shadow, Colour, HardCases };

struct StageRow {
    Stage stage;
    const char* name;                // moments | gaussian | sat | msm | robustness | final
    std::vector<std::string> files;  // the submission's files it compiles (final: stageFiles)
    // The kinds of image it is compared on (every light, cascade, layer and camera of each); the
    // first names the stage's image. A filter stage grades the first shadowing light's map only.
    std::vector<ImageKind> images;
    const char* input = "";          // the reference image it renders from ("": the scene alone)
    const char* filter = "";         // it applies to the scenes with this filter only ("": all)
    CompareBy compareBy = CompareBy::Moments;
    bool perScene = true;  // one test per scene; robustness is one test for the submission
    // The stage whose first render can show this one to be the stub everywhere, so that its
    // other renders (and the finals that use it) need not run (grade.cpp, scouts): itself for
    // moments and the filters, the hard cases for msm.glsl; none for final.
    std::optional<Stage> scoutedBy;
};

// The rows, in report order.
const std::vector<StageRow>& stageTable();
const StageRow& stageRow(Stage stage);
// The row named `name`; throws std::invalid_argument for any other name.
const StageRow& stageRow(const std::string& name);
const std::vector<std::string>& stageNames();  // the rows' names, in report order
// The submission files a stage compiles; final: the files of a scene with this filter.
std::vector<std::string> stageFiles(const StageRow& row, const std::string& filter);
// Whether the worker keeps image `name` for this stage (its kinds, never an msm_ image).
bool stageImage(const StageRow& row, const std::string& name);
// Whether `name` is graded for this stage: a stage image, and for the filters the first
// shadowing light's map (moments_filtered) and the per-pixel kernel image only.
bool gradedImage(const StageRow& row, const std::string& name);
// The stages whose submission files a render of `row` runs on a scene with `filter`: final runs
// moments, the scene's filter stage and msm; any other stage itself.
std::vector<const StageRow*> stagesRun(const StageRow& row, const std::string& filter);

}  // namespace sl::grader
