// batch.h: grading a folder of submissions (`shadowlab grade --batch DIR -j N`).
#pragma once

#include "grader.h"

namespace sl::grader {

// Grades every subfolder of `dir` into OUT/<name>/ (results.json, report/), N at a time, with
// a progress bar on stderr, and writes OUT/scores.csv: one row per submission, one column per
// stage. `base` gives the limits, scenes and reference mode. Returns the number graded.
// Each submission is graded by its own `shadowlab grade` child process, so that nothing one
// submission does (a crash of the grader itself included) can cost another its grade.
int gradeBatch(const fs::path& dir, int parallel, const GradeOptions& base);

// The summary a child's results.json holds (scores, per-stage tags, warnings).
GradeSummary summaryFromResults(const nlohmann::json& results);

}  // namespace sl::grader
