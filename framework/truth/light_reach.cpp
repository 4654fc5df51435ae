// light_reach: the pixels a light reaches (see light_reach.h).
#include "light_reach.h"

#include <cmath>

namespace sl {

glm::vec3 towardLight(const Light& light, const glm::vec3& p) {
    if (light.type == LightType::Directional)
        return glm::normalize(light.position - light.target);
    return glm::normalize(light.position - p);
}

Image lightReachMask(const Scene& scene, const VisiblePoints& points, int lightIndex,
                     int cameraIndex) {
    const Light& light = scene.lights.at(size_t(lightIndex));
    const Camera& cam = scene.cameras.at(size_t(cameraIndex));
    const glm::vec3 forward = glm::normalize(light.target - light.position);
    const float cosHalfCone = std::cos(glm::radians(light.coneDegrees * 0.5f));
    Image mask(points.width, points.height, 1);
    for (int y = 0; y < points.height; ++y)
        for (int x = 0; x < points.width; ++x) {
            if (!points.covered(x, y)) continue;
            const glm::vec3 p(points.position.at(x, y, 0), points.position.at(x, y, 1),
                              points.position.at(x, y, 2));
            glm::vec3 n(points.shadingNormal.at(x, y, 0), points.shadingNormal.at(x, y, 1),
                        points.shadingNormal.at(x, y, 2));
            if (glm::dot(n, cam.position - p) < 0.0f) n = -n;  // as lighting.frag: seen side
            const glm::vec3 l = towardLight(light, p);
            if (glm::dot(n, l) <= 0.0f) continue;               // diffuse = 0
            // lighting.frag's cone factor smoothstep(cosHalfCone, ..., c) is 0 for c <= it.
            if (light.type == LightType::Spot && glm::dot(-l, forward) <= cosHalfCone) continue;
            mask.at(x, y, 0) = 1.0f;
        }
    return mask;
}

int firstShadowingLight(const Scene& scene) {
    for (size_t i = 0; i < scene.lights.size(); ++i)
        if (scene.lights[i].castsShadows) return int(i);
    return -1;
}

}  // namespace sl
