// Mesh: triangle geometry for the scene's objects, in object space, plus their placement.
// Procedural shapes are tessellated here; OBJ files are read with tinyobjloader.
#pragma once

#include "scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace sl {

struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;      // one per position, unit length
    std::vector<std::uint32_t> indices;  // triangles, counter-clockwise seen from outside
};

struct Bounds {
    glm::vec3 lo{1e30f};
    glm::vec3 hi{-1e30f};
    void add(const glm::vec3& p) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
    bool empty() const { return lo.x > hi.x; }
};

// Tessellates an object's shape in object space. Throws SceneError for a mesh file that
// cannot be read (naming the scene file, the object and the OBJ path).
Mesh buildMesh(const Object& object, const Scene& scene);

// Object to world: scale, then rotate (x, then y, then z, degrees), then translate.
glm::mat4 objectToWorld(const Object& object);

// World-space bounds of a mesh placed with `objectToWorld`.
Bounds worldBounds(const Mesh& mesh, const glm::mat4& objectToWorld);

}  // namespace sl
