// batch.h: grading a folder of submissions (`shadowlab grade --batch DIR -j N`).
#pragma once

#include "grader.h"

namespace sl::grader {

// Grades every subfolder of `dir` into OUT/<name>/ (results.json, report/), N at a time, with
// a progress bar on stderr, and writes OUT/scores.csv: one row per submission, one column per
// stage. `base` gives the limits, scenes and reference mode. Returns the number graded.
// Each submission is graded by its own child process (a fork of the batch running
// gradeAndPrint, or `shadowlab grade` exec'd), so that nothing one submission does (a crash of
// the grader itself included) can cost another its grade.
int gradeBatch(const fs::path& dir, int parallel, const GradeOptions& base);

// What `shadowlab grade --submission` does once its options are read: grades, prints the score
// table and where the results are on stdout, the visible warnings on stderr. Returns the exit
// code (0: a results.json with scores; 1: the grader failed, results.json says why). A batch's
// children run this in a fork of the batch, or exec'd through the command line.
int gradeAndPrint(const GradeOptions& options);

// The row of scores.csv for a grade: the visible warnings as notes (those about hidden scenes
// counted, not named), or the reason the grader failed.
BatchRow batchRow(const GradeSummary& summary);

}  // namespace sl::grader
