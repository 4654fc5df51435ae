// gaussian_cases: the named input maps of `shadowlab probe gaussian --generate NAME`, small
// RGBA maps whose sizes leave work groups partly outside the image (7x5, 67x3, 3x67, 1x1).
#pragma once

#include "image.h"

#include <string>
#include <vector>

namespace sl {

struct GaussianCase {
    std::string name;  // "<kind>-<W>x<H>", e.g. "impulse-7x5"
    Image map;         // RGBA
};

// impulse, edge, constant, random (and "all": every one of them).
std::vector<std::string> gaussianCaseKinds();

// The maps of `kind` at the default sizes, or at width x height only when both are > 0:
//   impulse   0 everywhere but one texel at the centre, (1, 0.5, 0.25, 0.125)
//   edge      a step at each border, one per channel: 1 on the last column (b1), the first
//             row (b2), the first column (b3), the last row (b4), 0 elsewhere: a wrong edge
//             rule shows on the side it gets wrong
//   constant  the moments of depth 0.7 everywhere: a fixed point of the blur, border included
//   random    uniform in [0, 1), independently per texel and channel (fixed seed)
// Throws std::invalid_argument for an unknown kind.
std::vector<GaussianCase> gaussianCases(const std::string& kind, int width = 0, int height = 0);

}  // namespace sl
