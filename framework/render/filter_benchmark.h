// filter_benchmark: times the filter passes against copy passes over the same texture, in
// the same run, as CPU time of all the process's threads around glFinish (cost_clock.h: a core
// another process holds does not make a pass look slower), and reports medians, spreads and a
// verdict against the goals of docs/performance.md (machines are noisy and differ; ratios measured
// in one run travel). Two floors: the copy the goals are ratios to (copy.comp, one texel per
// invocation), which the verdict is against, and a tiled copy (copy_tile.comp, 4 texels of a row
// per invocation, the fastest copy measured on llvmpipe). The one-texel copy is bound by the cost
// of running invocations and work groups rather than by memory, so a tiled filter can run under 1.0
// of it; the ratio to the tiled copy says how far a pass is from what moving the texels costs.
#pragma once

#include "renderer.h"

#include <string>
#include <vector>

namespace sl {

struct BenchRow {
    std::string name;        // "gaussian r=8, y"
    double medianMs = 0;
    double baselineMs = 0;   // median of what it is compared with (copy passes, a lighting pass)
    double ratio = 0;        // medianMs / baselineMs
    double ratioMin = 0;     // spread: min-max over repeats of pass / baseline of that repeat
    double ratioMax = 0;
    double goal = 0;         // the ratio of instructions it should stay under (0: no goal)
    bool goalChecked = false; // instructions (the exact clock) at the goals' size: ✓ or ✗
    bool otherCompiler = false; // the exact clock, but an llvmpipe the goals were not measured on
    bool implemented = true; // false: the stage wrote the stub value -1 (not timed meaningfully)
    std::string baseline;    // "copy", "2 copies", "bilinear fetch"
    // Against the tiled copy (as many passes of it as `baseline` has copies): the honest
    // floor, reported beside the verdict's ratio. 0: not compared with it (lighting row).
    double tileBaselineMs = 0;
    double tileRatio = 0;    // medianMs / tileBaselineMs
};

// The goals hold for maps of this size (a pass's fixed cost per dispatch weighs more on a
// smaller one: the reference's r = 8 x pass is 7 copies at 32²). `./kit bench --exact`'s default.
constexpr int kBenchGoalSize = 256;

// "✓ ≤ 2.0", "✗ 2.013 > 2.0" (the exact clock; a miss shows the ratio with the digits that
// tell it from the goal), "≤ 2.0 in instructions (--exact)" (the CPU clock, or another size:
// shown, not checked), "≤ 2.0 on LLVM 15/19" (another compiler: goalsCompilerMismatch),
// "not implemented", or "" (no goal).
std::string benchVerdict(const BenchRow& row);

// "" where the goals hold as measured: x86-64 llvmpipe with 256-bit vectors and LLVM 15 or 19
// (Debian 12, 13). Else why a goal is shown, not checked, naming `renderer` (GL_RENDERER):
// another LLVM or vector width compiles the same GLSL into other instruction counts.
std::string goalsCompilerMismatch(const std::string& renderer);

struct BenchReport {
    std::string method;  // what a pass's cost is (cost_clock.h: CPU ms of all threads, or instructions)
    int size = 0;
    int repeats = 0;
    double copyMedianMs = 0;      // copy.comp, one texel per invocation
    double copyMinMs = 0, copyMaxMs = 0;  // its fastest and slowest repeat: the machine's noise
    double tileCopyMedianMs = 0;  // copy_tile.comp: the row "copy, <N> texels per invocation"
    int tileCopyTexels = 0;       // its N
    std::vector<BenchRow> rows;
    std::string goalsNote;  // goalsCompilerMismatch on the exact clock, "" where the goals hold
};

struct BenchOptions {
    int size = 1024;
    int repeats = 21;
    // Also time the lighting pass of `lightingScene` with its SAT lookup against the same scene
    // with a plain bilinear fetch of filtered moments (empty: skip).
    std::string lightingScene;
};

// Runs every measured pass `repeats` times, interleaved so that drifts in machine load hit
// them alike. The filters are the renderer's library's (normally reference/).
BenchReport runFilterBenchmark(Renderer& renderer, const BenchOptions& options);
inline BenchReport runFilterBenchmark(Renderer& renderer, int size, int repeats) {
    return runFilterBenchmark(renderer, BenchOptions{size, repeats, ""});
}

std::string formatBenchReport(const BenchReport& report);  // a Markdown table
std::string benchReportJson(const BenchReport& report);

}  // namespace sl
