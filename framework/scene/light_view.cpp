// light_view: light and camera matrices, automatic depth range (see light_view.h).
#include "light_view.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace sl {
namespace {

glm::vec3 upFor(const glm::vec3& forward) {
    // lookAt degenerates when looking along the up vector.
    return std::abs(glm::dot(glm::normalize(forward), glm::vec3(0, 1, 0))) > 0.99f
               ? glm::vec3(0, 0, 1)
               : glm::vec3(0, 1, 0);
}

}  // namespace

LightView computeLightView(const Light& light, const ShadowEffect& effect,
                           const std::vector<Bounds>& objectBounds) {
    LightView v;
    v.eye = light.position;
    v.forward = glm::normalize(light.target - light.position);
    v.view = glm::lookAt(light.position, light.target, upFor(v.forward));

    if (effect.depthRange) {
        v.depthRange = *effect.depthRange;
    } else {
        float lo = 1e30f, hi = -1e30f;
        for (const Bounds& b : objectBounds) {
            if (b.empty()) continue;
            for (int i = 0; i < 8; ++i) {
                glm::vec3 corner{(i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y,
                                 (i & 4) ? b.hi.z : b.lo.z};
                float d = glm::dot(corner - v.eye, v.forward);
                lo = std::min(lo, d);
                hi = std::max(hi, d);
            }
        }
        if (lo > hi) lo = 0.1f, hi = 10.0f;  // nothing in the scene
        lo = std::max(lo, 0.05f);
        hi = std::max(hi, lo + 0.01f);
        const float pad = 0.01f * (hi - lo);
        v.depthRange = {std::max(lo - pad, 0.05f), hi + pad};
    }
    if (light.type == LightType::Spot)
        v.projection = glm::perspective(glm::radians(light.coneDegrees), 1.0f, v.depthRange.x,
                                        v.depthRange.y);
    else
        v.projection = glm::ortho(-light.extent, light.extent, -light.extent, light.extent,
                                  v.depthRange.x, v.depthRange.y);
    v.viewProjection = v.projection * v.view;
    return v;
}

CameraView computeCameraView(const Camera& camera) {
    CameraView c;
    c.view = glm::lookAt(camera.position, camera.target, camera.up);
    c.projection = glm::perspective(glm::radians(camera.fovYDegrees),
                                    float(camera.width) / float(camera.height), camera.nearPlane,
                                    camera.farPlane);
    c.viewProjection = c.projection * c.view;
    return c;
}

glm::vec2 projectToPixel(const Camera& camera, const glm::vec3& world) {
    glm::vec4 clip = computeCameraView(camera).viewProjection * glm::vec4(world, 1.0f);
    glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(ndc.x * 0.5f + 0.5f) * camera.width, (0.5f - ndc.y * 0.5f) * camera.height};
}

}  // namespace sl
