// The reference stages on the GPU against independent double-precision CPU oracles
// (tests/oracles), on the public scenes' real moment maps. Each tolerance says where it
// comes from: u = 2^-24 is float32's unit roundoff.
#include "gl_test_support.h"
#include "oracles/moment_oracles.h"
#include "oracles/sat_offset.h"
#include "probe.h"

#include <cmath>
#include <random>

namespace sl {
namespace {

using oracle::u;  // float32's unit roundoff (moment_oracles.h)

// A moment map's 4 channels, as the oracles take them.
const std::vector<float>& px(const Image& img) { return img.pixels; }

Scene planeUnderSpot() {
    Scene s;
    s.name = "plane_under_spot";
    s.cameras.push_back(Camera{});
    Light l;
    l.position = {0, 5, 0};
    l.target = {0, 0, 0};
    s.lights.push_back(l);
    Object plane;
    plane.shape = ShapeType::Plane;
    plane.planeSize = {40, 40};
    s.objects.push_back(plane);
    s.shadow.filter = FilterKind::None;
    s.shadow.mapSize = 64;
    s.shadow.depthRange = glm::vec2(1.0f, 9.0f);
    return s;
}

}  // namespace

TEST(ReferenceVsOracle, RelativeDepthOfAPlaneFacingTheLight) {
    // Every point of a plane perpendicular to the light's axis lies 5 units along it:
    // z = (5 - 1) / (9 - 1) = 0.5 in every texel the plane covers (here: all of them).
    RenderResult r = test::renderScene(planeUnderSpot());
    const Image& raw = r.images.at("moments_raw");
    const glm::dvec4 expected = oracle::computeMoments(oracle::relativeDepth(5.0, 1.0, 9.0));
    for (int y = 0; y < raw.height; ++y)
        for (int x = 0; x < raw.width; ++x)
            for (int c = 0; c < 4; ++c)
                ASSERT_NEAR(raw.at(x, y, c), expected[c], 4 * u) << x << "," << y << " c" << c;
}

TEST(ReferenceVsOracle, ComputeMomentsOnArbitraryDepths) {
    test::sharedContext();
    std::vector<glm::vec3> inputs;
    for (int i = 0; i <= 200; ++i) inputs.push_back({-1.0f + 0.06f * i, 0.5f, 8.5f});
    auto gpu = probeMoments(test::library("reference"), inputs);
    for (size_t i = 0; i < inputs.size(); ++i) {
        glm::dvec4 want = oracle::computeMoments(
            oracle::relativeDepth(inputs[i].x, inputs[i].y, inputs[i].z));
        for (int c = 0; c < 4; ++c)  // a few float ops on values <= 1
            ASSERT_NEAR(gpu[i][c], want[c], 8 * u) << "lightDepth " << inputs[i].x;
    }
}

TEST(ReferenceVsOracle, UnfilteredMomentsArePowersOfOneDepth) {
    // Before filtering each texel holds one depth: b_k = b1^k (classic scene's real map).
    RenderResult r = test::renderScene(loadScene(test::scenePath("classic")));
    const Image& raw = r.images.at("moments_raw");
    for (int y = 0; y < raw.height; y += 3)
        for (int x = 0; x < raw.width; x += 3) {
            double z = raw.at(x, y, 0);
            for (int k = 2; k <= 4; ++k)
                ASSERT_NEAR(raw.at(x, y, k - 1), std::pow(z, k), 8 * u) << x << "," << y;
        }
}

TEST(ReferenceVsOracle, GaussianOnTheClassicScenesMoments) {
    Scene scene = loadScene(test::scenePath("classic"));
    ASSERT_EQ(scene.shadow.filter, FilterKind::Gaussian);
    RenderResult r = test::renderScene(scene);
    const Image& raw = r.images.at("moments_raw");
    const Image& gpu = r.images.at("moments_filtered");
    auto want = oracle::gaussianBlur2D(px(raw), raw.width, raw.height, scene.shadow.gaussianRadius,
                                       scene.shadow.gaussianSigma);
    // Per pass: 2r+1 products of values <= 1 with float weights summing to 1 (each weight off
    // by <= u): error <= (2r+2)·u; two passes, plus the rounding of the intermediate image.
    const double tol = 2 * (2 * scene.shadow.gaussianRadius + 3) * u;
    for (size_t i = 0; i < want.size(); ++i) ASSERT_NEAR(gpu.pixels[i], want[i], tol) << i;
}

TEST(ReferenceVsOracle, GaussianOnNonSquareMapsAndLargeRadii) {
    test::sharedContext();
    Renderer renderer(test::library("reference"));
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> d(0.0f, 1.0f);
    // 430 wide: 7 groups of 64 in the y pass, walked as a band of 4 and a narrower last band of
    // 3 (reference/gaussian_blur.comp, bandedGroup), so a texel left out or written twice shows.
    for (auto [w, h, radius] : {std::tuple{100, 37, 1}, {37, 100, 7}, {129, 65, 16}, {70, 90, 64},
                                {430, 41, 3}}) {
        Image src(w, h, 4);
        for (auto& v : src.pixels) v = d(rng);
        Texture a = Texture::create(w, h, GL_RGBA32F), b = Texture::create(w, h, GL_RGBA32F),
                c = Texture::create(w, h, GL_RGBA32F);
        a.upload(src);
        renderer.gaussianPass(a, b, radius, 0.0f, {1, 0});
        renderer.gaussianPass(b, c, radius, 0.0f, {0, 1});
        Image gpu = c.read();
        auto want = oracle::gaussianBlur2D(src.pixels, w, h, radius, 0.0);
        const double tol = 2 * (2 * radius + 3) * u;
        for (size_t i = 0; i < want.size(); ++i)
            ASSERT_NEAR(gpu.pixels[i], want[i], tol) << w << "x" << h << " r" << radius << " @" << i;
    }
}

TEST(ReferenceVsOracle, SummedAreaTableOnTheContactScenesMoments) {
    Scene scene = loadScene(test::scenePath("contact"));
    ASSERT_EQ(scene.shadow.filter, FilterKind::Sat);
    RenderResult r = test::renderScene(scene);
    const Image& raw = r.images.at("moments_raw");
    // reference/sat.comp stores each entry as two floats (docs/numerics.md): rebuild the
    // plain sums from them in double and compare those.
    const auto sat = oracle::plainSatFromOffsetTable(r.images.at("sat").pixels, raw.width, raw.height);
    auto want = oracle::summedAreaTable(px(raw), raw.width, raw.height);
    // Any float summation order of n non-negative terms errs by <= (n-1)·u·sum: rows then
    // columns give <= (w + h)·u·S (the two-float entries err by far less; the bound holds).
    const double growth = (raw.width + raw.height) * u;
    for (size_t i = 0; i < want.size(); ++i)
        ASSERT_NEAR(sat[i], want[i], growth * want[i] + 1e-6) << i;
}

// Odd sizes against the double-precision table: partial tiles, a last group with fewer
// columns than a work group (and than one quad of 4: reference/sat.comp walks 4 columns per
// invocation), rows not a multiple of the group's 32 lines, and lines of length 1.
TEST(ReferenceVsOracle, SatOnOddSizes) {
    test::sharedContext();
    Renderer renderer(test::library("reference"));
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> d(0.0f, 1.0f);
    for (auto [w, h] : {std::pair{130, 67}, {67, 130}, {1, 45}, {45, 1}, {33, 33}, {290, 3}}) {
        Image src(w, h, 4);
        for (auto& v : src.pixels) v = d(rng);
        Texture a = Texture::create(w, h, GL_RGBA32F),
                b = Texture::create(satTableWidth(w), h, GL_RGBA32F),
                c = Texture::create(satTableWidth(w), h, GL_RGBA32F);
        a.upload(src);
        renderer.satPass(a, b, {1, 0});
        renderer.satPass(b, c, {0, 1});
        const auto got = oracle::plainSatFromOffsetTable(c.read().pixels, w, h);
        const auto want = oracle::summedAreaTable(src.pixels, w, h);
        const double growth = (w + h) * u;
        for (size_t i = 0; i < want.size(); ++i)
            ASSERT_NEAR(got[i], want[i], growth * want[i] + 1e-6) << w << "x" << h << " @" << i;
    }
}

TEST(ReferenceVsOracle, SatBoxAverageOnTheGpuTable) {
    Scene scene = loadScene(test::scenePath("contact"));
    RenderResult r = test::renderScene(scene);
    // The stored table holds each entry as two floats (reference/sat.comp): the oracle's box
    // average reads the plain table rebuilt from them in double.
    const Image& gpu = r.images.at("moments_filtered");
    const Image& sat = gpu;  // the map's size (the table is twice as wide)
    const auto plain = oracle::plainSatFromOffsetTable(r.images.at("sat").pixels, sat.width, sat.height);
    const double k = scene.shadow.satKernelTexels;
    for (int y = 0; y < sat.height; y += 5)
        for (int x = 0; x < sat.width; x += 5) {
            glm::dvec2 c(x + 0.5, y + 0.5);
            glm::dvec4 want = oracle::satBoxAverage(plain, sat.width, sat.height, c, {k, k});
            // The GPU interpolates and combines 4 corners of the same table in double: what is
            // left is the float32 result's rounding. A float32 table would be off by ~u·S_max
            // divided by the box area: ~1e-2 here.
            for (int ch = 0; ch < 4; ++ch)
                ASSERT_NEAR(gpu.at(x, y, ch), want[ch], 1e-6) << x << "," << y << " c" << ch;
        }
}

TEST(ReferenceVsOracle, MomentShadowIntensityOnRealFilteredMoments) {
    Scene scene = loadScene(test::scenePath("classic"));
    RenderResult r = test::renderScene(scene);
    const Image& filtered = r.images.at("moments_filtered");
    std::vector<glm::vec4> b;
    std::vector<float> zf;
    for (int y = 0; y < filtered.height; y += 16)
        for (int x = 0; x < filtered.width; x += 16) {
            glm::vec4 m(filtered.at(x, y, 0), filtered.at(x, y, 1), filtered.at(x, y, 2),
                        filtered.at(x, y, 3));
            for (float dz : {-0.2f, -0.05f, 0.0f, 0.01f, 0.05f, 0.2f}) {
                b.push_back(m);
                zf.push_back(std::clamp(m.x + dz, 0.0f, 1.0f));
            }
        }
    const float alpha = scene.shadow.momentBias;
    auto gpu = probeMomentShadowIntensity(test::library("reference"), b, zf, alpha);
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> sign(0, 1);
    int checked = 0;
    for (size_t i = 0; i < b.size(); ++i) {
        ASSERT_TRUE(std::isfinite(gpu[i]) && gpu[i] >= 0.0f && gpu[i] <= 1.0f) << gpu[i];
        const glm::dvec4 bi(b[i]);
        const double want = oracle::msm4Hamburger(bi, zf[i], alpha);
        // Tolerance: how far G moves when the inputs move by float32 rounding (8u·|b|, random
        // signs). A backward-stable float solve errs by about that much; a bug errs by more.
        double sensitivity = 0.0;
        for (int trial = 0; trial < 8; ++trial) {
            glm::dvec4 p = bi;
            for (int c = 0; c < 4; ++c) p[c] += (sign(rng) ? 8 : -8) * u * std::abs(bi[c]);
            sensitivity = std::max(sensitivity, std::abs(oracle::msm4Hamburger(p, zf[i], alpha) - want));
        }
        ASSERT_NEAR(gpu[i], want, 4 * sensitivity + 1e-4)
            << "b=(" << b[i].x << "," << b[i].y << "," << b[i].z << "," << b[i].w << ") zf=" << zf[i];
        ++checked;
    }
    EXPECT_GT(checked, 1000);
}

}  // namespace sl
