// results.h: Gradescope's results.json and the terminal's score table.
#pragma once

#include "grader.h"
#include "rubric.h"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace sl::grader {

// `v` with `digits` digits after the point ("12.50"): points, percentages and metrics in text.
std::string fixedDigits(double v, int digits = 2);

// Points as results.json writes them: to the hundredth.
double round2(double v);

nlohmann::json resultsJson(const GradeSummary& summary, const Rubric& rubric);

// Writes `path` atomically (temp file + rename), so a reader never sees half a file.
void writeResults(const std::filesystem::path& path, const nlohmann::json& results);

// results.json for a grade that could not run: score 0, the reason in `output`.
void writeFailureResults(const std::filesystem::path& path, const std::string& reason,
                         double seconds);

// One row per stage: points, maximum, and the scenes that lost points. Visible tests only
// (stdout is shown to students): hidden scenes are counted, never named.
void printScoreTable(std::ostream& out, const GradeSummary& summary);

// Points per stage, summed over scenes (scores.csv: all; the table: visibleOnly).
std::map<std::string, std::pair<double, double>> stageTotals(const GradeSummary& summary,
                                                               bool visibleOnly = false);

// What students may see before the due date: the visible tests' points, how many hidden
// tests there are, and the warnings split into those that name no hidden scene and those
// that do (staff-only: they go into the hidden tests' own output).
struct VisibleSummary {
    double score = 0.0, maxScore = 0.0;
    int hiddenTests = 0;
    std::vector<std::string> warnings, hiddenWarnings;
};
VisibleSummary visibleSummary(const GradeSummary& summary);

}  // namespace sl::grader
