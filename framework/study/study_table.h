// study_table: the study's one table (docs/accuracy.md). One row per (scene, light size,
// technique, parameters): shadow-map bytes, pass and frame costs (CPU time, study_cost.h) with
// their ratio to a copy pass measured in the same run, and the error against both truths. Written as CSV, one row at a time, so an
// interrupted sweep keeps what it finished; read back to resume and to draw every figure.
#pragma once

#include "error_metrics.h"

#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace sl {

namespace fs = std::filesystem;

struct StudyRow {
    std::string scene, solution, technique, spec;  // spec: "vsm:bleedReduction=0.3"
    std::string filter;        // none | gaussian | sat
    int radius = 0;            // gaussian radius r (σ = r / 2); the SAT box has the same
                               // variance, r·√3 texels wide; 0: no filter
    double kernelTexels = 0;   // the filter's width in texels (Gaussian 2r + 1, SAT r·√3; 1 for none)
    int mapSize = 0;
    double lightSize = 0;      // the shadowing light's size (0: a point light, hard truth)
    int bits = 32;             // per channel of the map
    std::string parameters;    // the technique's resolved parameters, "name=value;..."
    size_t mapBytes = 0;       // the technique's map (all layers)
    size_t planBytes = 0;      // every shadow texture the plan allocates for the light
    int repeats = 0;
    // The frame's cost (cost_method: CPU ms of all threads, or millions of instructions), sum of
    // the planned passes, over the repeats.
    double frameMin = 0, frameMedian = 0, frameMax = 0;
    double frameWallMedian = 0;  // the same frames' wall time (moves with the host's load)
    std::string passTimes;     // "shadow=min/med/max;gaussian-x=...", the cost's unit
    double copyMillis = 0;     // the copy pass (1024² RGBA32F), the cost's unit, minimum over the
                               // repeats interleaved with the row's frames
    double frameRatio = 0;     // frameMin / copyMillis: travels between machines
    std::string costMethod;    // what the cost columns measure (study_cost.h)
    ShadowError truth;         // against the ray-traced truth
    ShadowError filtered;      // against the exact filtered visibility of the same map
    // Temporal stability (study_flicker.h): over flickerFrames frames of a turning light, the
    // mean frame-to-frame change of G minus the truth's (flickerTruth); 0 frames: not measured.
    int flickerFrames = 0;
    double flicker = 0, flickerTruth = 0;
    std::string reused;        // what this row took from earlier work, in words
    std::string mapKey;        // its raw shadow map: what, format, size, light, key digest
    std::string mapFrom;       // the row (key()) whose raw map it lit with; "": rendered its own
    std::string imageDigest;   // SHA-256 (16 hex digits) of the G image's floats: same bits, same digest
    std::string image, errorMap;  // files under the study folder

    std::string key() const;   // identifies the combination (resume)
};

// A number as the study's CSV, data files and pages print it (a printf format; the CSV's and
// the plots' data keep six significant digits, the report's tables fewer).
std::string formatNumber(double v, const char* format = "%.6g");

const std::string& studyCsvHeader();
std::string toCsvLine(const StudyRow& row);
// Reads a study CSV; throws std::runtime_error naming the file and line of a malformed row.
std::vector<StudyRow> readStudyCsv(const fs::path& path);
// Appends one row (writing the header first if the file is new) and flushes it to disk.
void appendStudyRow(const fs::path& path, const StudyRow& row);
// Writes the whole table (header and rows, in the order given) in place of the file.
void writeStudyCsv(const fs::path& path, const std::vector<StudyRow>& rows);

}  // namespace sl
