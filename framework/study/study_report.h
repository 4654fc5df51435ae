// study_report: the study's pictures, drawn from its table and nothing else: DIR/pareto.svg
// and .png (truth RMSE against frame/copy ratio, log-log, a marker per technique, a line through
// each technique's own best configurations, the Pareto front), DIR/pareto_bytes.* (against map
// bytes), and DIR/index.html (the plots, the Pareto-optimal configurations, and per technique
// its best image, its error map and the truth side by side). Plotting is gnuplot's
// (tools/study_plots.gp; docs/accuracy.md says why).
#pragma once

#include "study_table.h"

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace sl {

namespace fs = std::filesystem;

// Indices of the rows on the Pareto front of (x, y), both minimised, in increasing x.
std::vector<size_t> paretoFront(const std::vector<double>& x, const std::vector<double>& y);

// Writes DIR/plots/*.dat, runs gnuplot, writes DIR/index.html. `headline`: the machine, Mesa
// and LLVM versions, shown on the page. Throws std::runtime_error if gnuplot fails.
void writeStudyReport(const fs::path& dir, const std::vector<StudyRow>& rows, std::ostream& log,
                      const std::string& headline = "");

}  // namespace sl
