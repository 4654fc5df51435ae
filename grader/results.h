// results.h: Gradescope's results.json and the terminal's score table.
#pragma once

#include "grader.h"
#include "rubric.h"

#include <filesystem>
#include <ostream>
#include <string>

namespace sl::grader {

nlohmann::json resultsJson(const GradeSummary& summary, const Rubric& rubric);

// Writes `path` atomically (temp file + rename), so a reader never sees half a file.
void writeResults(const std::filesystem::path& path, const nlohmann::json& results);

// results.json for a grade that could not run: score 0, the reason in `output`.
void writeFailureResults(const std::filesystem::path& path, const std::string& reason,
                         double seconds);

// One row per stage: points, maximum, and the scenes that lost points.
void printScoreTable(std::ostream& out, const GradeSummary& summary);

// Points per stage, summed over scenes (scores.csv, the table).
std::map<std::string, std::pair<double, double>> stageTotals(const GradeSummary& summary);

}  // namespace sl::grader
