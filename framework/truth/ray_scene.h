// RayScene: the scene's shadow casters as an Embree BVH, for shadow rays. It holds the same
// tessellated triangles the rasteriser draws (mesh.h's buildMesh placed by objectToWorld), in
// float, so that the ray-traced truth and the shadow map see one and the same geometry.
#pragma once

#include "scene.h"

#include <glm/glm.hpp>

#include <memory>

namespace sl {

class RayScene {
public:
    explicit RayScene(const Scene& scene);  // casters only (Object::castsShadows)
    ~RayScene();
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    // True if a caster lies on the segment origin + t·direction, t in (tnear, tfar).
    // Thread-safe: any number of threads may trace at once.
    bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tnear,
                  float tfar) const;

    float sceneDiagonal() const { return diagonal_; }  // of the casters' bounds, world units

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    float diagonal_ = 1.0f;
};

}  // namespace sl
