// jobs.h: the worker command lines, folders and time limits one grade run shares with batch
// grading.
#pragma once

#include "grader.h"
#include "isolation.h"
#include "scene_list.h"

#include <map>

namespace sl::grader {

// OUT/.work-<pid>: the workers' scratch; per process, so that two grades into one OUT (two
// test runs at once) cannot delete each other's staged files.
fs::path workDir(const GradeOptions& o);

bool haveReference();  // reference/ holds all five stage files

// Mesa's shader cache for one grade's workers: a fresh folder in OUT/.work-<pid>/ (gone with
// it), so that a program compiled once (the reference's, a permutation shared by scenes) is
// not compiled again by the next worker, and nothing is shared between grades or submissions.
// Measured: a quarter of the shader-compile CPU. Empty when the folder cannot be made.
std::vector<std::pair<std::string, std::string>> shaderCacheEnvironment(const GradeOptions& o);

// The worker for one (scene, stage) (stage nullptr: the reference render), its images and log
// going to `out`. The log is scrubbed of the grader's own paths (submission/, shaders/ ... stay).
ChildSpec workerSpec(const GradeOptions& o, const GradedScene& scene, const StageRow* stage,
                     const fs::path& input, const fs::path& out);

// Time limits. With --timeout S: S for every render. Otherwise a render may take
// kTimeoutFactor times the reference's own render of that scene on this machine, at the same
// time, so that a busy machine gives the same grade (at least kTimeoutFloor seconds); without
// a reference render to time (goldens only), kTimeoutDefault.
constexpr double kTimeoutFactor = 10.0;
constexpr double kTimeoutFloor = 5.0;
constexpr double kTimeoutDefault = 20.0;
double stageTimeout(const GradeOptions& o, double referenceSeconds);
// How stageTimeout chose: " (20 x the reference's 0.41 s render)", " (--timeout)" or "".
std::string timeoutNote(const GradeOptions& o, double referenceSeconds);
double referenceTimeout(const GradeOptions& o);  // a reference render's own limit

// Golden mode: each scene's golden EXRs decoded once, by a child process, into
// OUT/.work-<pid>/golden/<scene>/<image>.raw (the same floats), which the probe check, the
// scoring and the workers' inputs then read. Reading an EXR in the grader would start OpenEXR's
// thread pool there, after which no worker can be forked (isolation.h): each was exec'd, and
// each that read a golden loaded the image codec again. An image that does not decode is read
// from its EXR as before (same messages).
void decodeGoldens(const GradeOptions& o, const std::vector<GradedScene>& scenes, const fs::path& goldens);

// The reference renders' seconds per scene, kept next to them (REF/times.json) for a batch.
std::map<std::string, double> readReferenceTimes(const fs::path& dir);

}  // namespace sl::grader
