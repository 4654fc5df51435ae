// report_diagnosis: known failure patterns, said in words for the report (a regrade request
// is answered faster when the report says "the moment bias looks missing" than when it shows
// 16 failing hard cases). Each finding names the evidence it is drawn from.
#pragma once

#include "grader.h"

#include <string>
#include <vector>

namespace sl::grader {

// Where one compared image's out-of-tolerance texels are (from its error map).
struct ImageFindings {
    std::string scene, stage, image;
    bool hidden = false;
    long failing = 0;          // texels/pixels outside tolerance
    long failingNearBorder = 0;  // of those, within `band` texels of the image's edge
    int band = 0;
    int reach = 0;             // the farthest of those from the edge, plus one (texels)
    long failingFar = 0;       // of the failing ones, in the half away from texel (0, 0)
    // Of those near the border, the ones along the edges away from texel (0, 0) only: where a
    // summed-area table's sums are largest (a border rule fails along the near edges too).
    long failingFarEdges = 0;
    long nonFinite = 0;
    // The moments stage's relativeDepth ladder (depth_ladder.h: one row of light depths, not
    // a map, so it has no border): its rows, and the failing ones outside [near, far].
    bool depthLadder = false;
    long rows = 0, failingOutsideRange = 0;
    // Of the failing rows, those whose b1 (z, relativeDepth's value) is off too; -1: not known.
    long failingDepth = -1;
};

// Counts an error map's failing texels (> 1) and those near the border; for the depth
// ladder's image (`image` kDepthLadderImage), the failing rows outside their depth range.
ImageFindings findImageProblems(const Image& errorMap, long nonFinite, const std::string& image = "");

// The depth ladder's failures in words: "the depth-ladder probe finds 36 of its 75 light depths
// off, all outside [near, far]: relativeDepth must clamp ..." (the moments test's first line,
// and the finding).
std::string depthLadderText(const ImageFindings& ladder);

// The patterns the summary's tests (and the images' findings) match, one sentence each.
// Hidden-scene tests count only with `includeHidden` (a student-visible report leaves them out).
std::vector<std::string> diagnose(const GradeSummary& summary,
                                  const std::vector<ImageFindings>& images, bool includeHidden);

}  // namespace sl::grader
