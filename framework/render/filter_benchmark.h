// filter_benchmark: times the filter passes against a plain copy pass over the same texture,
// in the same run, and reports medians and ratios (machines are noisy; ratios travel).
#pragma once

#include "renderer.h"

#include <string>
#include <vector>

namespace sl {

struct BenchRow {
    std::string name;    // "gaussian r=8, x"
    double medianMs = 0;
    double baselineMs = 0;  // median of the copy passes it is compared with
    double ratio = 0;       // medianMs / baselineMs
    double target = 0;      // the ratio it should stay under (0: none)
};

struct BenchReport {
    int size = 0;
    int repeats = 0;
    double copyMedianMs = 0;
    std::vector<BenchRow> rows;
};

// Runs every measured pass `repeats` times, interleaved so that drifts in machine load hit
// them alike. The filters are the renderer's library's (normally reference/).
BenchReport runFilterBenchmark(Renderer& renderer, int size, int repeats);

std::string formatBenchReport(const BenchReport& report);  // a Markdown table
std::string benchReportJson(const BenchReport& report);

}  // namespace sl
