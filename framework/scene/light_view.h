// light_view: the matrices and the depth range through which a light sees the scene, and the
// camera's matrices. The depth range turns light-space distances into relative depths.
#pragma once

#include "mesh.h"
#include "scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace sl {

struct LightView {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 viewProjection{1.0f};
    glm::vec3 eye{0.0f};        // lightDepth = dot(p - eye, forward)
    glm::vec3 forward{0.0f, 0.0f, -1.0f};
    glm::vec2 depthRange{0.1f, 10.0f};  // (near, far)
};

// `objectBounds`: world bounds of every object (receivers included) for the "auto" range:
// near = max(min distance of a bounds corner along `forward`, 0.05), far = max distance,
// both padded by 1% of far - near.
LightView computeLightView(const Light& light, const ShadowEffect& effect,
                           const std::vector<Bounds>& objectBounds);

struct CameraView {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 viewProjection{1.0f};
};

CameraView computeCameraView(const Camera& camera);

// World position -> pixel (x right, y down from the top row), as scene probes are written.
glm::vec2 projectToPixel(const Camera& camera, const glm::vec3& world);

}  // namespace sl
