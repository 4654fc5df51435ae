// metrics.h: how a student's image is compared with the reference (reasons: docs/grading.md).
#pragma once

#include "image.h"

#include <nlohmann/json.hpp>

#include <vector>

namespace sl::grader {

struct Comparison {
    double fraction = 0.0;      // texels/pixels within tolerance (NaN/Inf never are)
    long nonFinite = 0;         // NaN or Inf in the student's image
    long stubTexels = 0;        // every channel -1 (the stub value) where the reference is not
    std::string error;          // size or channel mismatch ("" if compared)
    Image errorMap;             // one channel: error / tolerance (<= 1 passes)
    // The worst texel (moment maps): error / tolerance there, where (x right, y up from the
    // bottom row, as GL stores it), which channel, and the two values. So that a student can
    // find a border bug that touches a handful of texels.
    double worst = 0.0;
    int worstX = -1, worstY = -1, worstChannel = -1;
    double worstValue = 0.0, worstExpected = 0.0;
    // OpenImageIO's figures, for the report only.
    double mean = 0, rms = 0, max = 0, psnr = 0;
    nlohmann::json toJson() const;
};

// Moment maps: a texel passes if every channel has |s − r| ≤ abs + rel·|r| + extra[c].
// `extra` (per channel, may be empty) widens the floor where float32 rounding of a correct
// implementation depends on its order of operations (summed-area tables).
Comparison compareMoments(const Image& student, const Image& reference, double absTol,
                          double relTol, const std::vector<double>& extra = {});

// Images (shadow G, final colour): a symmetric 3×3 Hausdorff distance. A pixel passes if the
// student's value is within `tol` (every channel) of some reference pixel in its 3×3
// neighbourhood, and the reference's value within `tol` of some student pixel in its own:
// a silhouette one pixel off (another llvmpipe build's rasterisation) passes; a wrong value
// does not.
Comparison compareImages(const Image& student, const Image& reference, double tol);

}  // namespace sl::grader
