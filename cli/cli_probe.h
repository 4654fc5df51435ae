// cli_probe: what the `shadowlab probe` subcommand's files share: its arguments, and the runs
// that live in their own files (cli_probe_gaussian.cpp, cli_probe_sweep.cpp).
#pragma once

#include "probe_cases.h"
#include "paths.h"

#include <string>

namespace sl::cli {

struct ProbeArgs {
    std::string function, solution = defaultSolution(), input, out, generate, map;
    float alpha = kReferenceMomentBias;
    int mapSize = 1024;
    // gaussian
    int radius = 4;
    float sigma = 0.0f;        // <= 0: radius / 2
    std::string passes = "xy";  // x, y or xy (x then y)
    std::string size;           // --generate: WxH instead of the default sizes
    // msm --sweep
    bool sweep = false;
    int vectors = 250000;
    unsigned long long seed = 20150225;
};

// `probe gaussian`: --generate writes maps; --input probes them (exit code; throws CsvError).
int runGaussianProbe(const ProbeArgs& a, const std::string& backend);

// `probe msm --sweep`: the property sweep on the solution, its summary on stdout.
int runMsmSweep(const ProbeArgs& a, const std::string& backend);

}  // namespace sl::cli
