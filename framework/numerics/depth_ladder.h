// depth_ladder: the relativeDepth ladder of the grader's moments stage. The shadow pass never
// produces a depth outside [near, far] (the light's frustum clips it), so a moment map cannot
// show whether relativeDepth clamps; the lighting pass feeds it such depths all the time. The
// moments stage therefore also probes computeMoments(relativeDepth(lightDepth, (near, far)))
// on this ladder of light depths in front of, inside and behind three depth ranges, and
// compares with the exact moments. `shadowlab probe moments --generate depth-ladder` writes
// the same rows, with the expected values, so that a student can reproduce a failure.
#pragma once

#include "image.h"

#include <glm/glm.hpp>

#include <vector>

namespace sl {

// The image name the grader's moments worker writes the ladder's results under (1 row).
inline constexpr const char* kDepthLadderImage = "moments_raw_depth_ladder";

// (lightDepth, near, far) per row.
const std::vector<glm::vec3>& relativeDepthLadder();

// computeMoments(clamp((d - near) / (far - near), 0, 1)) in double.
glm::dvec4 exactLadderMoments(glm::vec3 row);

// The ladder's exact moments as a width × 1 RGBA image (the grader's "reference").
Image depthLadderExpected();

// The ladder's results as that image, from probeMoments' output.
Image depthLadderImage(const std::vector<glm::vec4>& moments);

// True when every row looks like a stub relativeDepth (-1): computeMoments(-1) =
// (-1, 1, -1, 1) with a correct computeMoments, or (-1, -1, -1, -1) with a stub one.
bool depthLadderStub(const Image& ladder);

}  // namespace sl
