// Cascaded shadow maps (cascades.h): the split schemes against their formulas written out by
// hand, the scene keys and their errors, the plan (n cascades -> n sets of maps, n times the
// bytes, contiguous ranges), and on large_directional that cascades bring the shadow near the
// camera closer to the ray-traced truth than one map of the same size does.
#include "cascades.h"
#include "gl_test_support.h"
#include "scene_truth.h"
#include "technique.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

namespace sl {
namespace {

fs::path largeDirectional() { return test::root() / "scenes" / "ladder" / "large_directional.json"; }

nlohmann::json largeDirectionalJson() {
    std::ifstream in(largeDirectional());
    return nlohmann::json::parse(in);
}

// The loader's message for the scene with lights[0] changed by `edit`, or "" if it loads.
template <class Edit>
std::string loadError(Edit edit) {
    nlohmann::json j = largeDirectionalJson();
    edit(j["lights"][0]);
    try {
        parseScene(j.dump(), "large.json");
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(CascadeSplits, UniformLogarithmicAndPracticalFollowTheirFormulas) {
    const float n = 0.5f, f = 100.0f;
    const int N = 4;
    // By hand: uniform n + (f − n)·i/N; logarithmic n·(f/n)^(i/N); practical λ·log + (1 − λ)·uniform.
    const double uniform[] = {0.5, 25.375, 50.25, 75.125, 100.0};
    const double logarithmic[] = {0.5, 1.8803015, 7.0710678, 26.591479, 100.0};
    const auto u = cascadeSplits(n, f, N, CascadeSplit::Uniform, 0.0f);
    const auto l = cascadeSplits(n, f, N, CascadeSplit::Logarithmic, 0.0f);
    const auto p = cascadeSplits(n, f, N, CascadeSplit::Practical, 0.75f);
    ASSERT_EQ(u.size(), 5u);
    ASSERT_EQ(l.size(), 5u);
    ASSERT_EQ(p.size(), 5u);
    for (int i = 0; i <= N; ++i) {
        EXPECT_NEAR(u[i], uniform[i], 1e-4) << i;
        EXPECT_NEAR(l[i], logarithmic[i], 1e-4) << i;
        EXPECT_NEAR(p[i], 0.75 * logarithmic[i] + 0.25 * uniform[i], 1e-4) << i;
    }
    // λ = 0 is uniform, λ = 1 logarithmic.
    EXPECT_EQ(cascadeSplits(n, f, N, CascadeSplit::Practical, 0.0f), u);
    for (int i = 0; i <= N; ++i)
        EXPECT_NEAR(cascadeSplits(n, f, N, CascadeSplit::Practical, 1.0f)[i], l[i], 1e-4);
}

TEST(CascadeScene, KeysLoadAndBadValuesNameFileKeyAndExpectation) {
    nlohmann::json j = largeDirectionalJson();
    j["lights"][0]["cascades"] = 3;
    j["lights"][0]["cascadeSplit"] = "logarithmic";
    j["lights"][0].erase("cascadeLambda");  // only with the practical split
    const Scene s = parseScene(j.dump(), "large.json");
    EXPECT_EQ(s.lights[0].cascades, 3);
    EXPECT_EQ(s.lights[0].cascadeSplit, CascadeSplit::Logarithmic);

    std::string e = loadError([](nlohmann::json& l) { l["cascades"] = 5; });
    EXPECT_NE(e.find("large.json: /lights/0/cascades: expected an integer"), std::string::npos) << e;
    EXPECT_NE(e.find("found 5"), std::string::npos) << e;
    e = loadError([](nlohmann::json& l) { l["cascades"] = 2.5; });
    EXPECT_NE(e.find("/lights/0/cascades: expected an integer"), std::string::npos) << e;
    e = loadError([](nlohmann::json& l) { l["cascadeSplit"] = "linear"; });
    EXPECT_NE(e.find("/lights/0/cascadeSplit: expected one of \"uniform\", \"logarithmic\", "
                     "\"practical\""),
              std::string::npos)
        << e;
    e = loadError([](nlohmann::json& l) { l["cascadeLambda"] = 1.5; });
    EXPECT_NE(e.find("/lights/0/cascadeLambda: expected a number"), std::string::npos) << e;
    e = loadError([](nlohmann::json& l) {
        l["cascadeSplit"] = "uniform";
        l["cascadeLambda"] = 0.5;
    });
    EXPECT_NE(e.find("/lights/0/cascadeLambda: expected no cascadeLambda unless"), std::string::npos)
        << e;
    // A spot light has no cascades.
    e = loadError([](nlohmann::json& l) {
        l["type"] = "spot";
        for (const char* key : {"extent", "cascades", "cascadeSplit", "cascadeLambda"}) l.erase(key);
        l["cascades"] = 2;
    });
    EXPECT_NE(e.find("/lights/0/cascades: expected one of the keys"), std::string::npos) << e;
}

TEST(CascadePlan, NCascadesPlanNSetsOfMapsWithContiguousRanges) {
    Scene s = loadScene(largeDirectional().string());
    s.lights[0].cascades = 1;
    s.shadow.mapSize = 512;
    overrideTechnique(s.shadow, techniqueFromName("vsm"));
    s.shadow.filter = FilterKind::Gaussian;
    const PassPlan one = planPasses(s);
    EXPECT_TRUE(one.cascades.empty());
    for (int n : {2, 3, 4}) {
        s.lights[0].cascades = n;
        const PassPlan plan = planPasses(s);
        int raws = 0, shadowPasses = 0, blurs = 0;
        for (const PlannedTexture& t : plan.textures) raws += t.role == TextureRole::Raw;
        for (const PlannedPass& p : plan.passes) {
            shadowPasses += p.kind == PassKind::Shadow;
            blurs += p.kind == PassKind::GaussianX;
        }
        EXPECT_EQ(raws, n);
        EXPECT_EQ(shadowPasses, n);
        EXPECT_EQ(blurs, n);
        EXPECT_EQ(plan.bytes(), size_t(n) * one.bytes());
        for (int c = 0; c < n; ++c) {
            ASSERT_NE(plan.texture(0, TextureRole::Raw, c), nullptr);
            EXPECT_EQ(plan.texture(0, TextureRole::Raw, c)->width, 512);
            EXPECT_EQ(plan.bytes(0, c), one.bytes());
        }
        ASSERT_EQ(plan.cascades.size(), size_t(n));
        const glm::vec2 range = cascadeRange(s.cameras[0], sceneBounds(s));
        EXPECT_FLOAT_EQ(plan.cascades.front().nearDepth, range.x);
        EXPECT_FLOAT_EQ(plan.cascades.back().farDepth, range.y);
        for (int c = 1; c < n; ++c) {
            EXPECT_EQ(plan.cascades[c].nearDepth, plan.cascades[c - 1].farDepth);
            EXPECT_GT(plan.cascades[c].farDepth, plan.cascades[c].nearDepth);
        }
        const std::string explain = explainPlan(s, plan);
        EXPECT_NE(explain.find("light 0 cascade " + std::to_string(n - 1) + ": camera depth"),
                  std::string::npos)
            << explain;
    }
    // The scene's range: the ground ends well before the camera's far plane (120).
    EXPECT_LT(cascadeRange(s.cameras[0], sceneBounds(s)).y, 100.0f);
}

TEST(CascadeRender, CascadesBringTheShadowNearTheCameraCloserToTheTruth) {
    Scene s = loadScene(largeDirectional().string());
    s.cameras[0].width = 320;
    s.cameras[0].height = 180;
    s.shadow.mapSize = 512;
    overrideTechnique(s.shadow, techniqueFromName("hard"));
    s.lights[0].cascades = 1;
    test::sharedContext();
    SceneTruthOptions options;  // no cache: the test's scene is not a file
    const SceneTruth truth = computeSceneTruth(s, test::library("reference"), options);
    // Mean |G − G_true| over the pixels the light reaches in the lower 40% of the image (near
    // the camera; images are stored bottom row first), where one map's texels are largest on
    // screen.
    auto nearError = [&](const Image& g) {
        double sum = 0.0;
        int count = 0;
        for (int y = 0; y < int(0.4 * g.height); ++y)
            for (int x = 0; x < g.width; ++x) {
                if (truth.ray.reached.at(x, y, 0) < 0.5f) continue;
                sum += std::abs(g.at(x, y, 0) - truth.ray.shadow.at(x, y, 0));
                ++count;
            }
        return count ? sum / count : 1.0;
    };
    const RenderResult one = test::renderScene(s);
    s.lights[0].cascades = 4;
    const RenderResult four = test::renderScene(s);
    ASSERT_TRUE(four.images.count("moments_raw_cascade3"));
    const double e1 = nearError(one.images.at("shadow"));
    const double e4 = nearError(four.images.at("shadow"));
    // Measured: one 512² map 0.0031, four 512² cascades 0.0013.
    std::printf("near-camera mean |G - truth|: one map %.4f, 4 cascades %.4f\n", e1, e4);
    EXPECT_GT(e1, 0.002) << "one map must show its blockiness for the test to mean something";
    EXPECT_LT(e4, 0.6 * e1);
}

TEST(CascadeRender, RawMapsOfEveryCascadeFeedBackBitIdentically) {
    Scene s = loadScene(largeDirectional().string());
    s.cameras[0].width = 160;
    s.cameras[0].height = 90;
    s.shadow.mapSize = 256;
    overrideTechnique(s.shadow, techniqueFromName("vsm"));
    s.shadow.filter = FilterKind::Gaussian;
    s.lights[0].cascades = 3;
    test::sharedContext();
    Renderer renderer(test::library("reference"));
    RenderInputs keep;
    keep.keepRawMaps = true;
    const RenderResult first = renderer.render(s, planPasses(s), keep);
    ASSERT_EQ(first.rawMaps.at(0).cascades.size(), 2u);
    RenderInputs shared;
    shared.rawMaps = first.rawMaps;
    const RenderResult second = renderer.render(s, planPasses(s), shared);
    EXPECT_EQ(first.images.at("shadow").pixels, second.images.at("shadow").pixels);
    EXPECT_EQ(first.images.at("final").pixels, second.images.at("final").pixels);
}

}  // namespace sl
