// study_combinations: the study's sweep, enumerated: every light size × technique × map size ×
// filter × radius the technique table allows (a technique whose kernel the lighting picks per
// pixel runs one radius; one that allows none of the requested filters runs its own).
#pragma once

#include "scene.h"
#include "study.h"

#include <string>
#include <utility>
#include <vector>

namespace sl {

struct Combination {
    std::string spec;
    Technique technique;
    std::vector<std::pair<std::string, double>> params;
    double momentBias;  // < 0: the scene's
    FilterKind filter;
    int radius;
    int size;
    double lightSize;  // < 0: the scene's own lights
    bool perPixel = false;  // msm4:perPixel=1: the SAT's box per pixel (satKernelTexels)
};

// The combinations in the sweep's order; `notes` says what was narrowed and why.
std::vector<Combination> combinations(const StudyOptions& o, std::vector<std::string>& notes);

}  // namespace sl
