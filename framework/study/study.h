// study: the accuracy-versus-cost sweep (`shadowlab study`, docs/accuracy.md). Every
// combination of technique × shadow-map size × filter × radius is rendered through the real
// pipeline, timed as --explain times it, and compared with the ray-traced truth and with the
// exact filtered visibility; one CSV row each (study_table.h), then the plots and the page
// (study_report.h). Work is shared: the truth once per scene (and cached on disk), one depth
// map per (scene, light, size) for the filtered truths, each filtered truth once per kernel,
// and each technique's raw shadow map once per sweep for every row whose shadow pass would draw
// the same texels (raw_map_key.h: same light, size, format, shadow program and its uniforms):
// the rows differing only in filter and radius, and techniques storing the same map (hard, pcf
// and pcss share the depth map; msm4-hausdorff and msm-soft the moments). A sharing row's
// shadow pass does not run; it reports the shadow-pass time measured when the map was rendered.
#pragma once

#include "study_table.h"

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace sl {

namespace fs = std::filesystem;

struct StudyOptions {
    fs::path scene;
    std::vector<std::string> techniques;  // specs, "msm4" or "vsm:bleedReduction=0.3"
    std::vector<int> mapSizes = {256, 512, 1024, 2048};
    std::vector<int> radii = {1, 2, 4, 8, 16};      // Gaussian r; SAT box r·√3 texels (equal variance)
    std::vector<std::string> filters = {"gaussian", "sat"};
    // The light-size axis: every light of the scene gets each size in turn (0: a point light,
    // scored against the hard truth; > 0: a disk of that diameter, against its area truth).
    // Empty: the scene's own lights only.
    std::vector<double> lightSizes;
    int repeats = 3;
    // Temporal stability (study_flicker.h): frames of a light turning by flickerStep degrees
    // per frame; 0 (or 1): not measured.
    int flickerFrames = 0;
    double flickerStep = 0.2;
    std::string solution = "reference";
    int imageSize = 0;     // > 0: the main camera renders imageSize² (keeping nothing else)
    int samples = 1296;    // shadow rays per pixel for area lights (36², max SE < 0.005 here)
    fs::path out;
    fs::path cacheDir;     // the truth cache; empty: none
    bool explain = false;  // print each row's plan with its median times
    bool progress = true;  // a progress bar on stderr
    bool report = true;    // draw the plots and index.html at the end
    bool shareMaps = true; // share raw shadow maps between rows (false: every row renders its own)
    std::string headline;  // machine, Mesa and LLVM versions, for the page
    // Run only shard K of N (1-based; study_shard.h): whole groups of rows sharing a raw map.
    int shard = 1, shards = 1;
    // Study folders of shards whose rows (and images) are merged into `out` before the sweep,
    // which then runs only what is still missing and writes the table in the sweep's order.
    std::vector<fs::path> mergeFrom;
};

struct StudySummary {
    int planned = 0, run = 0, skipped = 0;  // skipped: already in the CSV (resumed)
    int shadowMapsRendered = 0;  // rows that ran their own shadow pass
    int sharedMaps = 0;          // rows that lit with a raw map an earlier row rendered
    bool truthFromCache = false;
    double truthSeconds = 0.0, maxStdError = 0.0;
    int samplesPerPixel = 1;
    std::vector<std::string> notes;  // what was reused, rows the technique table refused
};

// Every technique's default spec: the names of the technique table, in its order.
std::vector<std::string> allTechniqueSpecs();

// Needs a current GL context. Writes DIR/study.csv (appending; rows already there are skipped),
// DIR/rows/*.png, DIR/truth/*.png and, with `report`, the plots and index.html.
StudySummary runStudy(const StudyOptions& options, std::ostream& log);

}  // namespace sl
