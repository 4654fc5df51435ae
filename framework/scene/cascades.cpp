// cascades: split depths and per-slice light views (see cascades.h).
#include "cascades.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace sl {

std::vector<float> cascadeSplits(float nearDepth, float farDepth, int n, CascadeSplit scheme,
                                 float lambda) {
    std::vector<float> d(size_t(n) + 1);
    for (int i = 0; i <= n; ++i) {
        const double t = double(i) / n;
        const double uniform = nearDepth + (double(farDepth) - nearDepth) * t;
        const double logarithmic = nearDepth * std::pow(double(farDepth) / nearDepth, t);
        switch (scheme) {
            case CascadeSplit::Uniform: d[i] = float(uniform); break;
            case CascadeSplit::Logarithmic: d[i] = float(logarithmic); break;
            case CascadeSplit::Practical:
                d[i] = float(lambda * logarithmic + (1.0 - lambda) * uniform);
                break;
        }
    }
    d.front() = nearDepth;  // exact ends whatever pow rounds to
    d.back() = farDepth;
    return d;
}

glm::vec2 cascadeRange(const Camera& camera, const std::vector<Bounds>& objectBounds) {
    const glm::mat4 view = computeCameraView(camera).view;
    float lo = 1e30f, hi = -1e30f;
    for (const Bounds& b : objectBounds) {
        if (b.empty()) continue;
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 corner{(i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y,
                                   (i & 4) ? b.hi.z : b.lo.z};
            const float d = -(view * glm::vec4(corner, 1.0f)).z;
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        }
    }
    const float nearDepth = std::clamp(lo, camera.nearPlane, camera.farPlane);
    const float farDepth = std::min(camera.farPlane, hi);
    if (!(farDepth > nearDepth * 1.001f)) return {camera.nearPlane, camera.farPlane};
    return {nearDepth, farDepth};
}

std::vector<Bounds> sceneBounds(const Scene& scene) {
    std::vector<Bounds> out;
    for (const Object& o : scene.objects) out.push_back(worldBounds(buildMesh(o, scene), objectToWorld(o)));
    return out;
}

LightView fitCascade(const LightView& whole, const Camera& camera, float nearDepth,
                     float farDepth, int mapSize, float* halfWidth) {
    const glm::mat4 cameraToWorld = glm::inverse(computeCameraView(camera).view);
    const float tanY = std::tan(glm::radians(camera.fovYDegrees) * 0.5f);
    const float tanX = tanY * float(camera.width) / float(camera.height);
    // The slice's 8 corners in the light's view space.
    glm::vec3 corners[8];
    glm::vec3 centre(0.0f);
    for (int k = 0; k < 8; ++k) {
        const float depth = (k & 4) ? farDepth : nearDepth;
        const glm::vec4 viewPoint{((k & 1) ? 1.0f : -1.0f) * tanX * depth,
                                  ((k & 2) ? 1.0f : -1.0f) * tanY * depth, -depth, 1.0f};
        corners[k] = glm::vec3(whole.view * (cameraToWorld * viewPoint));
        centre += corners[k] / 8.0f;
    }
    float radius = 1e-3f;
    for (const glm::vec3& p : corners)
        radius = std::max(radius, glm::length(glm::vec2(p) - glm::vec2(centre)));
    const float texel = 2.0f * radius / float(mapSize);
    const glm::vec2 mid = glm::floor(glm::vec2(centre) / texel) * texel;
    LightView v = whole;
    v.projection = glm::ortho(mid.x - radius, mid.x + radius, mid.y - radius, mid.y + radius,
                              whole.depthRange.x, whole.depthRange.y);
    v.viewProjection = v.projection * v.view;
    if (halfWidth) *halfWidth = radius;
    return v;
}

}  // namespace sl
