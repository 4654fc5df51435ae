// stub_scouts: what a scout's render says for the renders it spares. A stub stage's output is
// -1 on every scene, so once one render of a stage (its scout) shows the stub everywhere, the
// stage's renders of the other scenes, and the finals that use it, are not run: they would
// score 0 as "not implemented" all the same (a first `./kit check` on the stubs renders 5 of 25
// tests). The scouts: the robustness test for msm.glsl (-1 on every hard case), the first
// moments, gaussian and sat renders for their stages (stubEverywhere in worker.json). Any
// other outcome of a scout renders everything. grade.cpp schedules them; these say what.
#pragma once

#include "scene_list.h"
#include "stages.h"
#include "worker.h"

#include <string>

namespace sl::grader {

// The note of a finished scout of `row` whose stage is the stub everywhere: every stub note of
// the stage's files, each function by name (or the files, when none names one); "" when its
// output is not the stub. `robustness`: the scout is the hard-case test (any stub note counts).
std::string scoutStubNote(const StageRow& row, bool robustness, const WorkerResult& w);

// A scout only speaks for the functions its scene runs: a per-pixel SAT scene also runs
// satKernelTexels, which a fixed-kernel scene's scout never probed (that render must run).
bool scoutSpeaksFor(Stage stage, bool scoutPerPixelSat, bool renderPerPixelSat);

// A scout's note as it applies to a render: without satKernelTexels for a fixed-kernel SAT
// scene (it never runs it), followed by where the scout saw the stub.
std::string spareReason(const std::string& note, Stage stage, bool renderPerPixelSat,
                        bool scoutIsRobustness, const GradedScene& scoutScene);

}  // namespace sl::grader
