// mesh: tessellates the scene's shapes (see mesh.h) and places them in the world.
// Conventions every shape keeps, and tests/test_scene.cpp checks: triangles are
// counter-clockwise seen from outside, normals have unit length, closed shapes are watertight
// (seams and poles reuse exactly the same positions), and no triangle has zero area.
#include "mesh.h"

#include <glm/gtc/matrix_transform.hpp>
#include <tiny_obj_loader.h>

#include <cmath>
#include <functional>
#include <string>

namespace sl {
namespace {

constexpr float kPi = 3.14159265358979323846f;

// Sphere, cylinder and torus resolution: fine enough that the faceting does not show in a
// 512² image, and that a sphere's area is within 0.3% of 4πr².
constexpr int kSphereSlices = 48, kSphereStacks = 24;
constexpr int kCylinderSegments = 48;
constexpr int kTorusMajor = 64, kTorusMinor = 24;

std::uint32_t addVertex(Mesh& m, const glm::vec3& p, const glm::vec3& n) {
    m.positions.push_back(p);
    m.normals.push_back(glm::normalize(n));
    return std::uint32_t(m.positions.size() - 1);
}

// Skips triangles that collapse at a pole (two corners on the same position).
void addTriangle(Mesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const glm::vec3 &pa = m.positions[a], &pb = m.positions[b], &pc = m.positions[c];
    if (pa == pb || pb == pc || pc == pa) return;
    m.indices.insert(m.indices.end(), {a, b, c});
}

// A (rows+1) × (cols+1) grid of vertices from a parametrisation (row i, column j) → position
// and normal. Orientation: the parametrisation must make (P(i+1,j) - P(i,j)) × (P(i,j+1) -
// P(i,j)) point outward.
void addGrid(Mesh& m, int rows, int cols,
             const std::function<void(int i, int j, glm::vec3& p, glm::vec3& n)>& at) {
    const std::uint32_t base = std::uint32_t(m.positions.size());
    for (int i = 0; i <= rows; ++i)
        for (int j = 0; j <= cols; ++j) {
            glm::vec3 p, n;
            at(i, j, p, n);
            addVertex(m, p, n);
        }
    auto id = [&](int i, int j) { return base + std::uint32_t(i * (cols + 1) + j); };
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < cols; ++j) {
            addTriangle(m, id(i, j), id(i + 1, j), id(i + 1, j + 1));
            addTriangle(m, id(i, j), id(i + 1, j + 1), id(i, j + 1));
        }
}

// cos and sin of 2π·k/n, exact at k = 0 and k = n, so that seams close without cracks.
glm::vec2 circle(int k, int n) {
    if (k % n == 0) return {1.0f, 0.0f};
    const float a = 2.0f * kPi * float(k) / float(n);
    return {std::cos(a), std::sin(a)};
}

// A rectangle centred on `center` with outward normal u × v, half-extents along u and v.
void addQuad(Mesh& m, const glm::vec3& center, const glm::vec3& u, const glm::vec3& v) {
    const glm::vec3 n = glm::cross(u, v);
    const std::uint32_t a = addVertex(m, center - u - v, n), b = addVertex(m, center + u - v, n),
                        c = addVertex(m, center + u + v, n), d = addVertex(m, center - u + v, n);
    addTriangle(m, a, b, c);
    addTriangle(m, a, c, d);
}

Mesh plane(const glm::vec2& size) {
    Mesh m;  // in xz, normal +y: (z × x) = y
    addQuad(m, glm::vec3(0.0f), {0.0f, 0.0f, 0.5f * size.y}, {0.5f * size.x, 0.0f, 0.0f});
    return m;
}

Mesh box(const glm::vec3& size) {
    Mesh m;
    const glm::vec3 h = 0.5f * size;
    const glm::vec3 x{h.x, 0, 0}, y{0, h.y, 0}, z{0, 0, h.z};
    // Each face: (u, v) with u × v along the outward normal.
    addQuad(m, x, y, z);
    addQuad(m, -x, z, y);
    addQuad(m, y, z, x);
    addQuad(m, -y, x, z);
    addQuad(m, z, x, y);
    addQuad(m, -z, y, x);
    return m;
}

Mesh sphere(float r) {
    Mesh m;
    // Row i: polar angle from +y (top) down; column j: azimuth, z = -sin so that the grid
    // orientation points outward.
    addGrid(m, kSphereStacks, kSphereSlices, [&](int i, int j, glm::vec3& p, glm::vec3& n) {
        const float theta = kPi * float(i) / float(kSphereStacks);
        const float s = (i == 0 || i == kSphereStacks) ? 0.0f : std::sin(theta);
        const float c = i == 0 ? 1.0f : i == kSphereStacks ? -1.0f : std::cos(theta);
        const glm::vec2 az = circle(j, kSphereSlices);
        n = {s * az.x, c, -s * az.y};
        p = r * n;
    });
    return m;
}

Mesh cylinder(float r, float height) {
    Mesh m;
    const float top = 0.5f * height;
    addGrid(m, 1, kCylinderSegments, [&](int i, int j, glm::vec3& p, glm::vec3& n) {
        const glm::vec2 az = circle(j, kCylinderSegments);
        n = {az.x, 0.0f, -az.y};
        p = {r * az.x, i == 0 ? top : -top, -r * az.y};
    });
    // Caps: fans around a centre vertex; the ring runs counter-clockwise seen from +y.
    for (float side : {1.0f, -1.0f}) {
        const glm::vec3 n{0.0f, side, 0.0f};
        const std::uint32_t centre = addVertex(m, {0.0f, side * top, 0.0f}, n);
        const std::uint32_t ring = std::uint32_t(m.positions.size());
        for (int j = 0; j < kCylinderSegments; ++j) {
            const glm::vec2 az = circle(j, kCylinderSegments);
            addVertex(m, {r * az.x, side * top, -r * az.y}, n);
        }
        for (int j = 0; j < kCylinderSegments; ++j) {
            const std::uint32_t a = ring + std::uint32_t(j);
            const std::uint32_t b = ring + std::uint32_t((j + 1) % kCylinderSegments);
            if (side > 0) addTriangle(m, centre, a, b);
            else addTriangle(m, centre, b, a);
        }
    }
    return m;
}

Mesh torus(float major, float minor) {
    Mesh m;
    // Row i: angle around the tube, running downward on the outer equator; column j: angle
    // around the y axis (z = -sin), as for the sphere.
    addGrid(m, kTorusMinor, kTorusMajor, [&](int i, int j, glm::vec3& p, glm::vec3& n) {
        const glm::vec2 tube = circle(i, kTorusMinor);
        const glm::vec2 az = circle(j, kTorusMajor);
        const glm::vec3 radial{az.x, 0.0f, -az.y};
        n = tube.x * radial - glm::vec3(0.0f, tube.y, 0.0f);
        p = major * radial + minor * n;
    });
    return m;
}

[[noreturn]] void objError(const Object& object, const Scene& scene, const std::string& why) {
    std::string where = "/objects/?/path";
    for (size_t i = 0; i < scene.objects.size(); ++i)
        if (&scene.objects[i] == &object || scene.objects[i].name == object.name) {
            where = "/objects/" + std::to_string(i) + "/path";
            break;
        }
    throw SceneError(scene.path + ": " + where + ": expected a readable OBJ file for object \"" +
                     object.name + "\", found \"" + object.meshPath + "\" (" + why + ")");
}

// OBJ through tinyobjloader. Every triangle corner becomes its own vertex. Corners without a
// normal in the file get a smooth one: the area-weighted mean of the faces around the same
// position, counting only faces within 60° of this one, so that hard edges stay hard.
Mesh objMesh(const Object& object, const Scene& scene) {
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(object.meshPath, config)) {
        std::string err = reader.Error();
        while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
        objError(object, scene, err.empty() ? "cannot parse it" : err);
    }
    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    const size_t positionCount = attrib.vertices.size() / 3;
    auto position = [&](int k) {
        return glm::vec3(attrib.vertices[3 * k], attrib.vertices[3 * k + 1],
                         attrib.vertices[3 * k + 2]);
    };

    struct Face {
        tinyobj::index_t corner[3];
        glm::vec3 normal;  // area-weighted (unnormalised cross product)
    };
    std::vector<Face> faces;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const auto& idx = shape.mesh.indices;
        for (size_t f = 0; f + 3 <= idx.size(); f += 3) {
            Face face{{idx[f], idx[f + 1], idx[f + 2]}, glm::vec3(0.0f)};
            for (const auto& c : face.corner)
                if (c.vertex_index < 0 || size_t(c.vertex_index) >= positionCount)
                    objError(object, scene, "a face refers to a missing vertex");
            const glm::vec3 p0 = position(face.corner[0].vertex_index);
            face.normal = glm::cross(position(face.corner[1].vertex_index) - p0,
                                     position(face.corner[2].vertex_index) - p0);
            if (glm::length(face.normal) > 0.0f) faces.push_back(face);  // drop degenerate ones
        }
    }
    if (faces.empty()) objError(object, scene, "it has no triangles");

    std::vector<std::vector<size_t>> facesAt(positionCount);
    for (size_t f = 0; f < faces.size(); ++f)
        for (const auto& c : faces[f].corner) facesAt[size_t(c.vertex_index)].push_back(f);

    const float creaseCos = 0.5f;  // cos 60°
    Mesh m;
    for (const Face& face : faces) {
        const glm::vec3 unit = glm::normalize(face.normal);
        std::uint32_t ids[3];
        for (int k = 0; k < 3; ++k) {
            const tinyobj::index_t c = face.corner[k];
            glm::vec3 n(0.0f);
            if (c.normal_index >= 0 && size_t(3 * c.normal_index + 2) < attrib.normals.size())
                n = {attrib.normals[3 * c.normal_index], attrib.normals[3 * c.normal_index + 1],
                     attrib.normals[3 * c.normal_index + 2]};
            if (!(glm::length(n) > 0.0f)) {
                for (size_t g : facesAt[size_t(c.vertex_index)])
                    if (glm::dot(glm::normalize(faces[g].normal), unit) > creaseCos)
                        n += faces[g].normal;
                if (!(glm::length(n) > 0.0f)) n = unit;
            }
            ids[k] = addVertex(m, position(c.vertex_index), n);
        }
        addTriangle(m, ids[0], ids[1], ids[2]);
    }
    return m;
}

}  // namespace

Mesh buildMesh(const Object& object, const Scene& scene) {
    switch (object.shape) {
        case ShapeType::Plane: return plane(object.planeSize);
        case ShapeType::Box: return box(object.boxSize);
        case ShapeType::Sphere: return sphere(object.radius);
        case ShapeType::Cylinder: return cylinder(object.radius, object.height);
        case ShapeType::Torus: return torus(object.majorRadius, object.minorRadius);
        case ShapeType::Mesh: return objMesh(object, scene);
    }
    return {};
}

glm::mat4 objectToWorld(const Object& object) {
    const glm::vec3 r = glm::radians(object.rotateDegrees);
    glm::mat4 m = glm::translate(glm::mat4(1.0f), object.translate);
    m = glm::rotate(m, r.z, glm::vec3(0, 0, 1));
    m = glm::rotate(m, r.y, glm::vec3(0, 1, 0));
    m = glm::rotate(m, r.x, glm::vec3(1, 0, 0));
    return glm::scale(m, object.scale);  // T · Rz · Ry · Rx · S
}

Bounds worldBounds(const Mesh& mesh, const glm::mat4& toWorld) {
    Bounds b;
    for (const glm::vec3& p : mesh.positions) b.add(glm::vec3(toWorld * glm::vec4(p, 1.0f)));
    return b;
}

}  // namespace sl
