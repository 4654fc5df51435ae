// A float32, line-by-line CPU mirror of reference/msm.glsl (test-only code). The property
// sweep checks that the GPU agrees with it, so that a difference between llvmpipe and plain
// IEEE float32 (fused multiply-adds, flushed denormals, a miscompile) shows up, and so that
// the properties can be checked on the CPU at the same time. Keep in step with the shader.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace sl::mirror {

inline float msmCappedQuotient(float x, float y) {
    const float safeY = (y < 0.0f) ? std::min(y, -1e-30f) : std::max(y, 1e-30f);
    return std::clamp(x / safeY, -1e10f, 1e10f);
}

inline float momentShadowIntensity(glm::vec4 b, float zf, float alpha) {
    b = b * (1.0f - alpha) + glm::vec4(0.5f) * alpha;  // GLSL mix(b, vec4(0.5), α)
    const float D22 = std::max(b.y - b.x * b.x, 1e-10f);
    const float L32 = (b.z - b.x * b.y) / D22;
    const float D33 = std::max(b.w - b.y * b.y - L32 * L32 * D22, 1e-10f);
    const float y2 = zf - b.x;
    const float y3 = zf * zf - b.y - L32 * y2;
    glm::vec3 c;
    c.z = y3 / D33;
    c.y = y2 / D22 - L32 * c.z;
    c.x = 1.0f - b.x * c.y - b.y * c.z;
    c /= std::max(std::max(std::abs(c.x), std::abs(c.y)), std::abs(c.z));
    const float sqrtDisc = std::sqrt(std::max(c.y * c.y - 4.0f * c.x * c.z, 0.0f));
    const float q = -0.5f * (c.y + (c.y < 0.0f ? -sqrtDisc : sqrtDisc));
    const float rootA = msmCappedQuotient(q, c.z);
    const float rootB = (q == 0.0f) ? rootA : msmCappedQuotient(c.x, q);
    const float z2 = std::min(rootA, rootB), z3 = std::max(rootA, rootB);
    float G;
    if (z3 < zf) {
        const float w1 = (z2 * z3 - b.x * (z2 + z3) + b.y) / std::max((zf - z2) * (zf - z3), 1e-30f);
        G = 1.0f - w1;
    } else if (z2 < zf) {
        G = (zf * z3 - b.x * (zf + z3) + b.y) / std::max((z3 - z2) * (zf - z2), 1e-30f);
    } else {
        G = 0.0f;
    }
    return std::clamp(G, 0.0f, 1.0f);
}

}  // namespace sl::mirror
