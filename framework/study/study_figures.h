// study_figures: the data behind the study's figures beyond the Pareto front, drawn from the
// table alone (study_report.h runs gnuplot on them):
// - the Pareto markers' encoding: point type = technique, point size = map size, colour =
//   kernel (filter and radius), and a y range fitted to the data;
// - cost against kernel size, per technique and filter, at one map size (what Peters et al.
//   2016 plot: PCF's lighting grows with the kernel's area, a Gaussian with its width, a SAT not);
// - per-pass cost bars (shadow, filter, lighting), per technique, at one configuration.
#pragma once

#include "study_table.h"

#include <filesystem>
#include <string>
#include <vector>

namespace sl {

namespace fs = std::filesystem;

// A Pareto marker's size for a map size: 256² 0.6, each doubling +0.35.
double markerSize(int mapSize);
// A kernel's colour ("#rrggbb"): none black, Gaussian blues and SAT oranges, darker as r grows.
std::string kernelColour(const std::string& filter, int radius);
// A kernel's name in the legend: "none", "gaussian r4", "sat r4".
std::string kernelName(const std::string& filter, int radius);

// The pass costs of a row (pass_cost's medians), grouped: shadow, filter (widen, Gaussian, SAT),
// lighting; in the cost's unit.
struct PassGroups {
    double shadow = 0, filter = 0, lighting = 0;
};
PassGroups passGroups(const StudyRow& row);

// The map size the kernel and pass figures use: 1024 if the rows have it, else the largest.
int figureMapSize(const std::vector<const StudyRow*>& rows);

// Writes, into `plots`, kernel_<i>.dat (radius, frame/copy, filter passes/copy, lighting/copy:
// one technique and filter each, at figureMapSize; names in `kernelSeries`) and passes.dat (one
// line per technique: its configuration at figureMapSize with the smallest radius, Gaussian
// where it has one; shadow, filter, lighting over the copy pass). Returns the gnuplot variables
// that name them: "kseries='...'; kmap=1024".
std::string writeKernelAndPassData(const fs::path& plots, const std::vector<const StudyRow*>& rows);

// Writes flicker_<i>.dat (map size, flicker, the truth's own change: one technique each, at
// its smallest kernel, Gaussian where it has one) when the rows measured flicker. Returns
// "fseries='...'", or "" when no row did.
std::string writeFlickerData(const fs::path& plots, const std::vector<const StudyRow*>& rows);

}  // namespace sl
