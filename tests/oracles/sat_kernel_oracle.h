// sat_kernel_oracle: satKernelTexels (sat_lookup.glsl) in double, from an exact summed-area
// table: the blocker search of variance soft shadow mapping (Yang et al. 2010) over the
// search box, then the penumbra by similar triangles. Instructor only: it solves the stage.
#pragma once

#include "oracles/moment_oracles.h"

#include <algorithm>
#include <vector>

namespace sl::oracle {

struct SatKernelInput {
    glm::dvec2 center;
    double searchTexels, zr;
    glm::dvec2 depthRange;  // (near, far), world units along the light's axis
    double lightTexels;
    bool perspective;
    glm::dvec2 kernelRange;
};

// The same guards as the reference: nothing in front of the receiver (zr at or in front of
// the box's mean) gives the smallest box, and the penumbra fades in with the blocker share.
inline double satKernelTexels(const std::vector<double>& sat, int w, int h,
                              const SatKernelInput& in, double minVariance = 1e-7) {
    const glm::dvec4 b = satBoxAverage(sat, w, h, in.center, glm::dvec2(in.searchTexels));
    const double mu = b.x, var = std::max(b.y - mu * mu, minVariance);
    if (in.zr <= mu) return in.kernelRange.x;
    const double d = in.zr - mu;
    const double unoccluded = var / (var + d * d);
    const double share = 1.0 - unoccluded;
    if (share < 1e-6) return in.kernelRange.x;
    const double zb = std::clamp((mu - unoccluded * in.zr) / share, 0.0, in.zr);
    const double dr = in.depthRange.x + in.zr * (in.depthRange.y - in.depthRange.x);
    const double db = in.depthRange.x + zb * (in.depthRange.y - in.depthRange.x);
    const double wTexels =
        in.lightTexels * (dr - db) / (in.perspective ? std::max(db, 1e-4 * in.depthRange.y) : 1.0);
    // The penumbra fades in over the first 5 % of blocker share (no jump where it is unsure).
    const double fade = std::clamp(share / 0.05, 0.0, 1.0);
    return in.kernelRange.x + fade * (std::clamp(wTexels, in.kernelRange.x, in.kernelRange.y) -
                                      in.kernelRange.x);
}

}  // namespace sl::oracle
