// Tests of the scene's geometry (framework/scene/mesh.cpp): every shape has unit normals and
// triangles wound counter-clockwise seen from outside, closed shapes are watertight and
// enclose the right volume, and objects are placed by T * Rz * Ry * Rx * S.
#include "gl_test_support.h"
#include "mesh.h"
#include "scene.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <tuple>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using namespace sl;

// A scratch directory of this test process, for the OBJ files the tests write.
fs::path scratchDir() {
    const char* env = std::getenv("SHADOWLAB_TEST_TMP");
    fs::path dir = (env ? fs::path(env) : fs::temp_directory_path()) /
                   ("test_mesh_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

Object shape(ShapeType type) {
    Object o;
    o.name = toString(type);
    o.shape = type;
    o.radius = 0.75f;
    o.height = 1.5f;
    o.boxSize = {1.0f, 2.0f, 3.0f};
    o.majorRadius = 1.0f;
    o.minorRadius = 0.3f;
    return o;
}

double signedVolume(const Mesh& m) {
    double v = 0.0;
    for (size_t i = 0; i < m.indices.size(); i += 3)
        v += glm::dot(glm::dvec3(m.positions[m.indices[i]]),
                      glm::cross(glm::dvec3(m.positions[m.indices[i + 1]]),
                                 glm::dvec3(m.positions[m.indices[i + 2]]))) / 6.0;
    return v;
}

double area(const Mesh& m) {
    double a = 0.0;
    for (size_t i = 0; i < m.indices.size(); i += 3) {
        const glm::dvec3 p0 = m.positions[m.indices[i]], p1 = m.positions[m.indices[i + 1]],
                         p2 = m.positions[m.indices[i + 2]];
        a += 0.5 * glm::length(glm::cross(p1 - p0, p2 - p0));
    }
    return a;
}

// Unit normals; every corner's normal on the outer side of its triangle (counter-clockwise
// winding seen from where the normals point); no degenerate triangle.
void expectWellFormed(const Mesh& m) {
    ASSERT_EQ(m.positions.size(), m.normals.size());
    ASSERT_EQ(m.indices.size() % 3, 0u);
    for (const glm::vec3& n : m.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    for (size_t i = 0; i < m.indices.size(); i += 3) {
        ASSERT_LT(std::max({m.indices[i], m.indices[i + 1], m.indices[i + 2]}), m.positions.size());
        const glm::vec3 p0 = m.positions[m.indices[i]], p1 = m.positions[m.indices[i + 1]],
                        p2 = m.positions[m.indices[i + 2]];
        const glm::vec3 face = glm::cross(p1 - p0, p2 - p0);
        ASSERT_GT(glm::length(face), 0.0f) << "degenerate triangle " << i / 3;
        for (int k = 0; k < 3; ++k)
            EXPECT_GT(glm::dot(glm::normalize(face), m.normals[m.indices[i + k]]), 0.0f)
                << "triangle " << i / 3 << " corner " << k;
    }
}

// Closed and consistently wound: every directed edge (by position) is matched by exactly one
// edge running the other way.
void expectWatertight(const Mesh& m) {
    using Key = std::tuple<float, float, float, float, float, float>;
    std::map<Key, int> edges;
    auto key = [](const glm::vec3& a, const glm::vec3& b) {
        return Key{a.x, a.y, a.z, b.x, b.y, b.z};
    };
    for (size_t i = 0; i < m.indices.size(); i += 3)
        for (int k = 0; k < 3; ++k)
            ++edges[key(m.positions[m.indices[i + k]], m.positions[m.indices[i + (k + 1) % 3]])];
    int bad = 0;
    for (const auto& [e, count] : edges) {
        const Key reverse{std::get<3>(e), std::get<4>(e), std::get<5>(e),
                          std::get<0>(e), std::get<1>(e), std::get<2>(e)};
        auto it = edges.find(reverse);
        if (count != 1 || it == edges.end() || it->second != 1) ++bad;
    }
    EXPECT_EQ(bad, 0) << "unmatched edges";
}

TEST(SceneMesh, ShapesAreWellFormedClosedAndHaveTheRightVolume) {
    const Scene scene;
    const float pi = glm::pi<float>();
    const std::vector<std::pair<ShapeType, double>> closed = {
        {ShapeType::Box, 1.0 * 2.0 * 3.0},
        {ShapeType::Sphere, 4.0 / 3.0 * pi * 0.75 * 0.75 * 0.75},
        {ShapeType::Cylinder, pi * 0.75 * 0.75 * 1.5},
        {ShapeType::Torus, 2.0 * pi * pi * 1.0 * 0.3 * 0.3},
    };
    for (const auto& [type, volume] : closed) {
        SCOPED_TRACE(toString(type));
        const Mesh m = buildMesh(shape(type), scene);
        expectWellFormed(m);
        expectWatertight(m);
        EXPECT_NEAR(signedVolume(m), volume, 0.02 * volume);  // positive: wound outward
    }
    const Mesh plane = buildMesh(shape(ShapeType::Plane), scene);
    expectWellFormed(plane);
    for (const glm::vec3& n : plane.normals) EXPECT_EQ(n, glm::vec3(0, 1, 0));
}

TEST(SceneMesh, SphereAreaWithinOnePercent) {
    Object o = shape(ShapeType::Sphere);
    o.radius = 2.0f;
    const double exact = 4.0 * glm::pi<double>() * 4.0;
    EXPECT_NEAR(area(buildMesh(o, Scene{})), exact, 0.01 * exact);
}

TEST(SceneMesh, BoxAndPlaneSizes) {
    const Mesh box = buildMesh(shape(ShapeType::Box), Scene{});
    EXPECT_GE(box.indices.size() / 3, 12u);
    EXPECT_NEAR(area(box), 2.0 * (1 * 2 + 2 * 3 + 1 * 3), 1e-4);
    Object p = shape(ShapeType::Plane);
    p.planeSize = {4.0f, 6.0f};
    const Bounds b = worldBounds(buildMesh(p, Scene{}), glm::mat4(1.0f));
    EXPECT_EQ(b.lo, glm::vec3(-2, 0, -3));
    EXPECT_EQ(b.hi, glm::vec3(2, 0, 3));
}

TEST(SceneMesh, TransformedBoxBounds) {
    Object o = shape(ShapeType::Box);
    o.boxSize = {2.0f, 1.0f, 1.0f};
    o.scale = {1.0f, 2.0f, 1.0f};        // -> 2 x 2 x 1
    o.rotateDegrees = {0.0f, 90.0f, 0.0f};  // x extent becomes z extent
    o.translate = {1.0f, 2.0f, 3.0f};
    const Bounds b = worldBounds(buildMesh(o, Scene{}), objectToWorld(o));
    const glm::vec3 lo{0.5f, 1.0f, 2.0f}, hi{1.5f, 3.0f, 4.0f};
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(b.lo[i], lo[i], 1e-5f) << "axis " << i;
        EXPECT_NEAR(b.hi[i], hi[i], 1e-5f) << "axis " << i;
    }
}

TEST(SceneMesh, RotationAppliesXThenYThenZ) {
    Object o;
    o.rotateDegrees = {90.0f, 90.0f, 0.0f};
    o.scale = glm::vec3(2.0f);
    o.translate = {10.0f, 0.0f, 0.0f};
    // (0, 1, 0) -scale-> (0, 2, 0) -Rx 90-> (0, 0, 2) -Ry 90-> (2, 0, 0) -T-> (12, 0, 0).
    const glm::vec4 p = objectToWorld(o) * glm::vec4(0, 1, 0, 1);
    EXPECT_NEAR(p.x, 12.0f, 1e-5f);
    EXPECT_NEAR(p.y, 0.0f, 1e-5f);
    EXPECT_NEAR(p.z, 0.0f, 1e-5f);
}

TEST(SceneMesh, ObjWithoutNormalsGetsFlatNormalsAtHardEdges) {
    // A unit cube, counter-clockwise quads, no normals.
    const fs::path obj = scratchDir() / "cube.obj";
    test::writeFile(obj, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                         "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n");
    Object o;
    o.name = "cube";
    o.shape = ShapeType::Mesh;
    o.meshPath = obj.string();
    const Mesh m = buildMesh(o, Scene{});
    EXPECT_EQ(m.indices.size(), 36u);
    expectWellFormed(m);
    expectWatertight(m);
    EXPECT_NEAR(signedVolume(m), 1.0, 1e-5);
    for (const glm::vec3& n : m.normals)  // 90° edges are hard: every normal is axis-aligned
        EXPECT_NEAR(std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)}), 1.0f, 1e-5f);
}

TEST(SceneMesh, ObjNormalsFromTheFileAreKept) {
    const fs::path obj = scratchDir() / "tri.obj";
    test::writeFile(obj, "v 0 0 0\nv 1 0 0\nv 0 0 -1\nvn 0 2 0\nvn 0.6 0.8 0\nvn 0 1 0\n"
                         "f 1//1 2//2 3//3\n");
    Object o;
    o.shape = ShapeType::Mesh;
    o.meshPath = obj.string();
    const Mesh m = buildMesh(o, Scene{});
    ASSERT_EQ(m.normals.size(), 3u);
    EXPECT_EQ(m.normals[0], glm::vec3(0, 1, 0));  // normalised
    EXPECT_NEAR(m.normals[1].x, 0.6f, 1e-6f);
}

TEST(SceneMesh, StarObjOfThinSceneIsClosed) {
    const Scene scene = loadScene(test::scenePath("thin"));
    for (const Object& o : scene.objects)
        if (o.shape == ShapeType::Mesh) {
            const Mesh m = buildMesh(o, scene);
            expectWellFormed(m);
            expectWatertight(m);
            EXPECT_GT(signedVolume(m), 0.0);
        }
}

TEST(SceneMesh, UnreadableObjNamesSceneObjectAndPath) {
    Scene scene;
    scene.path = "scenes/x.json";
    Object o;
    o.name = "statue";
    o.shape = ShapeType::Mesh;
    o.meshPath = "scenes/meshes/gone.obj";
    scene.objects = {shape(ShapeType::Box), o};
    try {
        buildMesh(scene.objects[1], scene);
        FAIL() << "no SceneError";
    } catch (const SceneError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind("scenes/x.json: /objects/1/path: expected ", 0), 0u) << message;
        EXPECT_NE(message.find("\"statue\""), std::string::npos) << message;
        EXPECT_NE(message.find("found \"scenes/meshes/gone.obj\""), std::string::npos) << message;
    }
}

}  // namespace
