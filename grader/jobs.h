// jobs.h: the worker command lines and folders one grade run shares with batch grading.
#pragma once

#include "grader.h"
#include "isolation.h"
#include "scene_list.h"

namespace sl::grader {

// OUT/.work-<pid>: the workers' scratch; per process, so that two grades into one OUT (two
// test runs at once) cannot delete each other's staged files.
fs::path workDir(const GradeOptions& o);

bool haveReference();  // reference/ holds all five stage files

// `shadowlab grade-worker ...` for one (scene, stage), its images and log going to `out`.
ChildSpec workerSpec(const GradeOptions& o, const GradedScene& scene, const std::string& stage,
                     const fs::path& input, const fs::path& out);

}  // namespace sl::grader
