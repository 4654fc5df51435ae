// scene_rays: world-space triangles per object, a slab test on each object's bounds, then
// Möller-Trumbore on its triangles, in double precision (no acceleration structure: a tool
// casts a few thousand rays at scenes of a few thousand triangles).
#include "scene_rays.h"

#include <algorithm>
#include <cmath>

namespace sl {

SceneRays::SceneRays(const Scene& scene) {
    for (const Object& object : scene.objects) {
        const Mesh mesh = buildMesh(object, scene);
        const glm::mat4 model = objectToWorld(object);
        bounds_.push_back(worldBounds(mesh, model));
        Part part;
        part.caster = object.castsShadows;
        part.lo = glm::dvec3(bounds_.back().lo);
        part.hi = glm::dvec3(bounds_.back().hi);
        std::vector<glm::dvec3> world;
        for (const auto& p : mesh.positions) world.push_back(glm::dvec3(model * glm::vec4(p, 1.0f)));
        for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            const glm::dvec3 a = world[mesh.indices[i]];
            part.triangles.push_back({a, world[mesh.indices[i + 1]] - a, world[mesh.indices[i + 2]] - a});
        }
        parts_.push_back(std::move(part));
    }
}

namespace {

bool slab(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& lo, const glm::dvec3& hi,
          double tMin, double tMax) {
    const double pad = 1e-6 * (1.0 + glm::length(hi - lo));
    for (int k = 0; k < 3; ++k) {
        if (std::fabs(d[k]) < 1e-300) {
            if (o[k] < lo[k] - pad || o[k] > hi[k] + pad) return false;
            continue;
        }
        double t0 = (lo[k] - pad - o[k]) / d[k], t1 = (hi[k] + pad - o[k]) / d[k];
        if (t0 > t1) std::swap(t0, t1);
        tMin = std::max(tMin, t0);
        tMax = std::min(tMax, t1);
        if (tMin > tMax) return false;
    }
    return true;
}

}  // namespace

RayHit SceneRays::first(const glm::dvec3& o, const glm::dvec3& d, double tMin, double tMax,
                        bool castersOnly) const {
    RayHit best;
    best.t = tMax;
    for (size_t k = 0; k < parts_.size(); ++k) {
        const Part& part = parts_[k];
        if ((castersOnly && !part.caster) || !slab(o, d, part.lo, part.hi, tMin, best.t)) continue;
        for (const Triangle& tri : part.triangles) {
            const glm::dvec3 p = glm::cross(d, tri.e2);
            const double det = glm::dot(tri.e1, p);
            if (std::fabs(det) < 1e-300) continue;  // parallel (both faces count: no culling)
            const double inv = 1.0 / det;
            const glm::dvec3 s = o - tri.a;
            const double u = glm::dot(s, p) * inv;
            if (u < 0.0 || u > 1.0) continue;
            const glm::dvec3 q = glm::cross(s, tri.e1);
            const double v = glm::dot(d, q) * inv;
            if (v < 0.0 || u + v > 1.0) continue;
            const double t = glm::dot(tri.e2, q) * inv;
            if (t > tMin && t < best.t) {
                best.t = t;
                best.object = int(k);
            }
        }
    }
    if (!best.hit()) best.t = std::numeric_limits<double>::infinity();
    return best;
}

}  // namespace sl
