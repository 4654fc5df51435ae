// light_reach: which camera pixels a light reaches, the same way lighting.frag decides it
// (covered, the visible side facing the light, inside a spot light's cone). Truth and error
// metrics are taken over these pixels only: elsewhere G does not change the image.
#pragma once

#include "image.h"
#include "scene.h"
#include "visible_points.h"

#include <glm/glm.hpp>

namespace sl {

// Unit direction from p towards the light's centre (directional: -forward).
glm::vec3 towardLight(const Light& light, const glm::vec3& p);

// 1 where `light` reaches the pixel's visible point, else 0 (one channel, rows bottom first).
Image lightReachMask(const Scene& scene, const VisiblePoints& points, int lightIndex,
                     int cameraIndex = 0);

// The first light that casts shadows (the one the "shadow" image shows), or -1.
int firstShadowingLight(const Scene& scene);

}  // namespace sl
