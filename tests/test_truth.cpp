// The ray-traced truth against analytic answers: a sphere over a plane under a point light (the
// exact shadow, an ellipse: the cone of rays tangent to the sphere cut by the ground) and under
// a disk light (the visible fraction of the disk, integrated finely against the exact sphere).
// The expected values never use the truth's own code: segment-sphere tests in double.
#include "gl_test_support.h"
#include "image_io.h"
#include "ray_scene.h"
#include "ray_truth.h"
#include "scene_truth.h"
#include "visible_points.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

namespace sl {
namespace {

const glm::dvec3 kCentre(0.3, 1.6, -0.2);
constexpr double kRadius = 0.8;
// The tessellated sphere (48 × 24, vertices on the sphere) lies within R(1 - cos 5.4°) of it:
// the farthest point of a facet from the sphere is the middle of a quad's diagonal.
constexpr double kSag = kRadius * (1.0 - 0.99556196);

Scene sphereScene(const std::string& name, double lightSize) {
    const fs::path dir = test::tempDir("truth_" + name);
    const fs::path file = dir / (name + ".json");
    std::ofstream(file) << R"({
  "camera": {"position": [0, 9, 0.01], "target": [0, 0, 0], "up": [0, 0, -1], "fovYDegrees": 40,
             "near": 0.1, "far": 50, "width": 128, "height": 128},
  "lights": [{"type": "spot", "position": [1.2, 5.5, 0.6], "target": [0, 0, 0],
              "coneDegrees": 100, "size": )" << lightSize << R"(}],
  "objects": [
    {"name": "ground", "shape": "plane", "size": [12, 12]},
    {"name": "ball", "shape": "sphere", "radius": 0.8, "translate": [0.3, 1.6, -0.2]}],
  "shadow": {"mapSize": 256, "filter": {"type": "gaussian", "radius": 2}, "depthBias": 0.002}
})";
    return loadScene(file.string());
}

// Signed distance from the sphere's centre to the segment q -> s, minus the radius (< 0: blocked).
double segmentClearance(const glm::dvec3& q, const glm::dvec3& s) {
    const glm::dvec3 d = s - q;
    const double t = std::clamp(glm::dot(kCentre - q, d) / glm::dot(d, d), 0.0, 1.0);
    return glm::length(q + t * d - kCentre) - kRadius;
}

glm::dvec3 pointAt(const VisiblePoints& v, int x, int y) {
    return {v.position.at(x, y, 0), v.position.at(x, y, 1), v.position.at(x, y, 2)};
}

TEST(Truth, PointLightShadowOfASphereIsTheExactEllipse) {
    const Scene scene = sphereScene("point", 0.0);
    test::sharedContext();
    const VisiblePoints points = renderVisiblePoints(scene, test::library("reference"));
    RayScene rays(scene);
    const RayTruth truth = traceRayTruth(scene, rays, points, 0, 0, {});
    EXPECT_EQ(truth.samplesPerPixel, 1);
    const glm::dvec3 light(scene.lights[0].position);
    int ground = 0, shadowed = 0, band = 0, wrong = 0;
    for (int y = 0; y < points.height; ++y)
        for (int x = 0; x < points.width; ++x) {
            if (truth.reached.at(x, y, 0) < 0.5f) continue;
            const glm::dvec3 q = pointAt(points, x, y);
            if (std::abs(q.y) > 1e-4) continue;  // ground points only
            ++ground;
            const double clearance = segmentClearance(q, light);
            const float expected = clearance < 0 ? 1.0f : 0.0f;
            shadowed += clearance < 0;
            // Within the faceting's reach of the silhouette the tessellated answer may differ.
            if (std::abs(clearance) < kSag + 1e-4) { ++band; continue; }
            if (truth.shadow.at(x, y, 0) != expected) ++wrong;
        }
    EXPECT_GT(ground, 8000);
    EXPECT_GT(shadowed, 400) << "the sphere's shadow should be in view";
    EXPECT_LT(band, shadowed / 10);
    EXPECT_EQ(wrong, 0) << "pixels whose hard visibility differs from the exact ellipse";
}

TEST(Truth, DiskLightPenumbraMatchesAFineIntegralOverTheDisk) {
    const Scene scene = sphereScene("disk", 1.2);
    test::sharedContext();
    const VisiblePoints points = renderVisiblePoints(scene, test::library("reference"));
    RayScene rays(scene);
    RayTruthOptions options;
    options.samples = 1024;
    const RayTruth truth = traceRayTruth(scene, rays, points, 0, 0, options);
    EXPECT_EQ(truth.samplesPerPixel, 1024);
    // Reference: 48 rings × 96 sectors of equal area on the disk, in double, against the exact
    // sphere and against the sphere inscribed in the tessellation: the tessellated truth must
    // lie between the two (within its standard error).
    const Light& l = scene.lights[0];
    const double rL = 0.5 * l.size;
    const glm::dvec3 centre(l.position), f = glm::normalize(glm::dvec3(l.target - l.position));
    const glm::dvec3 u = glm::normalize(glm::cross(f, glm::dvec3(0, 0, 1))), v = glm::cross(f, u);
    const int rings = 48, sectors = 96;
    double sumAbs = 0, sumSigned = 0, maxSe = 0;
    int penumbra = 0, outside = 0;
    for (int y = 0; y < points.height; ++y)
        for (int x = 0; x < points.width; ++x) {
            if (truth.reached.at(x, y, 0) < 0.5f) continue;
            const glm::dvec3 q = pointAt(points, x, y);
            if (std::abs(q.y) > 1e-4) continue;
            // Every ray to the disk passes within rL of the ray to its centre.
            if (std::abs(segmentClearance(q, centre)) > rL + kSag) continue;
            int blockedOuter = 0, blockedInner = 0;
            for (int i = 0; i < rings; ++i)
                for (int j = 0; j < sectors; ++j) {
                    const double r = rL * std::sqrt((i + 0.5) / rings);
                    const double a = 2 * M_PI * (j + 0.5) / sectors;
                    const double c = segmentClearance(q, centre + r * std::cos(a) * u + r * std::sin(a) * v);
                    blockedOuter += c < 0;
                    blockedInner += c < -kSag;
                }
            const double hi = double(blockedOuter) / (rings * sectors);
            const double lo = double(blockedInner) / (rings * sectors);
            if (hi <= 0.0 || lo >= 1.0) continue;
            ++penumbra;
            const double g = truth.shadow.at(x, y, 0), se = truth.stdError.at(x, y, 0);
            const double mid = 0.5 * (lo + hi);
            sumAbs += std::abs(g - mid);
            sumSigned += g - mid;
            maxSe = std::max(maxSe, se);
            // 3 standard errors, plus the reference grid's own resolution.
            outside += g < lo - 3 * se - 0.003 || g > hi + 3 * se + 0.003;
        }
    ASSERT_GT(penumbra, 300) << "the penumbra should be in view";
    EXPECT_LT(std::abs(sumSigned / penumbra), 0.002) << "a bias: wrong emitter size or frame?";
    EXPECT_LT(sumAbs / penumbra, 0.006);
    EXPECT_LT(maxSe, 0.0101) << "stated standard error of 1024 stratified rays";
    EXPECT_LE(outside, penumbra / 100) << "more than 1% of penumbra pixels outside the bounds";
    std::printf("disk penumbra: %d pixels, mean |G - ref| %.5f, mean signed %.5f, max SE %.5f, "
                "%d outside\n", penumbra, sumAbs / penumbra, sumSigned / penumbra, maxSe, outside);
}

TEST(Truth, SameBytesAtAnyThreadCount) {
    const Scene scene = sphereScene("threads", 1.0);
    test::sharedContext();
    const VisiblePoints points = renderVisiblePoints(scene, test::library("reference"));
    RayScene rays(scene);
    RayTruthOptions one, two;
    one.samples = two.samples = 64;
    one.threads = 1;
    two.threads = 2;
    const RayTruth a = traceRayTruth(scene, rays, points, 0, 0, one);
    const RayTruth b = traceRayTruth(scene, rays, points, 0, 0, two);
    EXPECT_EQ(a.shadow.pixels, b.shadow.pixels);
    EXPECT_EQ(a.stdError.pixels, b.stdError.pixels);
    const fs::path d1 = test::tempDir("truth_bytes1"), d2 = test::tempDir("truth_bytes2");
    SceneTruth t1, t2;
    t1.ray = a;
    t2.ray = b;
    writeTruthFiles(t1, d1);
    writeTruthFiles(t2, d2);
    EXPECT_EQ(sha256File(d1 / "truth.exr"), sha256File(d2 / "truth.exr"));
}

TEST(Truth, CacheIsKeyedByTheSceneAndReadBack) {
    const Scene scene = sphereScene("cache", 0.0);
    Scene moved = scene;
    test::sharedContext();
    SceneTruthOptions o;
    o.cacheDir = test::tempDir("truth_cache");
    const SceneTruth first = computeSceneTruth(scene, test::library("reference"), o);
    const SceneTruth second = computeSceneTruth(scene, test::library("reference"), o);
    EXPECT_FALSE(first.fromCache);
    EXPECT_TRUE(second.fromCache);
    EXPECT_EQ(first.ray.shadow.pixels, second.ray.shadow.pixels);
    EXPECT_EQ(first.ray.reached.pixels, second.ray.reached.pixels);
    moved.cameras[0].width = 64;  // another image: another key
    EXPECT_NE(sceneTruthHash(moved, o), first.hash);
}

TEST(Truth, LightSizeIsADiskDiameterOrARectangle) {
    const fs::path dir = test::tempDir("truth_light_size");
    auto load = [&](const std::string& size) {
        std::ofstream(dir / "s.json") << R"({"camera": {"position": [0, 3, 3], "target": [0, 0, 0]},
            "lights": [{"type": "spot", "position": [0, 5, 0],
            "target": [0, 0, 0], "size": )" << size << R"(}],
            "objects": [{"name": "g", "shape": "plane", "size": 4}]})";
        return loadScene((dir / "s.json").string());
    };
    const Scene disk = load("0.5");
    EXPECT_FLOAT_EQ(disk.lights[0].size, 0.5f);
    EXPECT_EQ(disk.lights[0].rectangle, glm::vec2(0.0f));
    const Scene rect = load("[2, 0.5]");
    EXPECT_EQ(rect.lights[0].rectangle, glm::vec2(2.0f, 0.5f));
    EXPECT_FLOAT_EQ(rect.lights[0].size, 2.0f);
    try {
        load("[1, 2, 3]");
        FAIL() << "a three-number size loaded";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("size"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("[width, height]"), std::string::npos) << e.what();
    }
}

// A directional light's size is an angle, as pcss and msm-soft read it (penumbra = size · the
// blocker-to-receiver distance): seen from the target, its emitter samples span that angle
// whatever the light's distance; a spot light's disk keeps its width in world units.
TEST(Truth, DirectionalLightSizeIsAnAngleSeenFromTheTarget) {
    Light sun;
    sun.type = LightType::Directional;
    sun.target = glm::vec3(1, 0, 2);
    sun.size = 0.05f;
    for (float distance : {2.0f, 14.0f}) {
        sun.position = sun.target + distance * glm::normalize(glm::vec3(-3, 4, 1));
        const glm::vec3 axis = glm::normalize(sun.position - sun.target);
        float widest = 0.0f;
        const int m = 16;
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < m; ++i) {
                const glm::vec3 d = glm::normalize(emitterSample(sun, i, j, m, 0.999f, 0.5f) - sun.target);
                widest = std::max(widest, std::acos(std::min(1.0f, glm::dot(d, axis))));
            }
        // The outermost strata reach the rim: half the angle, to the jitter's last 1/m.
        EXPECT_LE(widest, 0.5f * sun.size * 1.001f) << distance;
        EXPECT_GE(widest, 0.5f * sun.size * (1.0f - 1.0f / m)) << distance;
    }
    Light spot = sun;
    spot.type = LightType::Spot;
    const glm::vec3 s = emitterSample(spot, 1, 0, 2, 0.999f, 0.5f);
    EXPECT_NEAR(glm::length(s - spot.position), 0.5f * spot.size, 0.01f * spot.size);
}

}  // namespace
}  // namespace sl
