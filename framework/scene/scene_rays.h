// scene_rays: CPU rays against a scene's triangles (the same tessellation the renderer draws),
// for tools that reason about geometry without rendering: `shadowlab project` uses it to say
// which surface a camera or a shadow-map texel sees first.
#pragma once

#include "mesh.h"
#include "scene.h"

#include <glm/glm.hpp>

#include <limits>
#include <vector>

namespace sl {

struct RayHit {
    double t = std::numeric_limits<double>::infinity();  // origin + t * direction
    int object = -1;                                      // index into scene.objects; -1: none
    bool hit() const { return object >= 0; }
};

class SceneRays {
public:
    explicit SceneRays(const Scene& scene);  // throws SceneError for an unreadable mesh

    // The nearest triangle hit with t in (tMin, tMax); `castersOnly` skips objects with
    // castsShadows false (what a shadow map sees).
    RayHit first(const glm::dvec3& origin, const glm::dvec3& direction, double tMin, double tMax,
                 bool castersOnly) const;

    const std::vector<Bounds>& bounds() const { return bounds_; }  // per object, world space

private:
    struct Triangle {
        glm::dvec3 a, e1, e2;
    };
    struct Part {
        std::vector<Triangle> triangles;
        glm::dvec3 lo, hi;
        bool caster;
    };
    std::vector<Part> parts_;
    std::vector<Bounds> bounds_;
};

}  // namespace sl
