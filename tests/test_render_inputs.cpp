// RenderInputs (renderer.h): a light's raw shadow map read back from one render and fed into
// another stands in for the shadow pass bit-exactly, in every map format (R32F depth, RG32F,
// RGBA32F moments, RGBA16 quantised moments, CSM's layers, second-depth's peeled map), and
// the filter passes and lighting still run on it. This is what lets the technique sweep render a
// shadow map once per (scene, light, size, format) and share it between techniques.
#include "gl_test_support.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <cstring>

namespace sl {
namespace {

// box_on_plane at test size.
Scene smallScene(Technique t, FilterKind filter) {
    Scene s = loadScene((test::root() / "scenes" / "ladder" / "box_on_plane.json").string());
    overrideTechnique(s.shadow, t);
    s.shadow.filter = filter;
    s.shadow.mapSize = 256;
    s.shadow.gaussianRadius = 3;
    s.shadow.gaussianSigma = 1.5f;
    s.shadow.satKernelTexels = 7.0f;
    for (Camera& c : s.cameras) c.width = 160, c.height = 120;
    return s;
}

bool sameBytes(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.channels == b.channels &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

struct Case {
    Technique technique;
    FilterKind filter;
};

std::string name(const Case& c) {
    return techniqueRow(c.technique).name + "/" + toString(c.filter);
}

RenderResult render(const Scene& s, const RenderInputs& inputs) {
    test::sharedContext();
    Renderer renderer(test::library("reference"));
    return renderer.render(s, planPasses(s), inputs);
}

}  // namespace

TEST(RenderInputs, RawMapFedBackRendersBitIdentically) {
    const std::vector<Case> cases = {
        {techniqueFromName("hard"), FilterKind::None},        {techniqueFromName("second-depth"), FilterKind::None},
        {techniqueFromName("pcf"), FilterKind::Gaussian},     {techniqueFromName("vsm"), FilterKind::Gaussian},
        {techniqueFromName("vsm"), FilterKind::Sat},          {techniqueFromName("msm4"), FilterKind::Gaussian},
        {techniqueFromName("msm4"), FilterKind::Sat},         {techniqueFromName("msm4-hausdorff"), FilterKind::Sat},
        {techniqueFromName("msm4-16bit"), FilterKind::Gaussian}, {techniqueFromName("csm"), FilterKind::Gaussian},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(name(c));
        const Scene s = smallScene(c.technique, c.filter);
        RenderInputs keep;
        keep.keepRawMaps = true;
        const RenderResult first = render(s, keep);
        ASSERT_EQ(first.rawMaps.size(), 1u);
        const RawShadowMap& raw = first.rawMaps.at(0);
        ASSERT_FALSE(raw.raw.empty());
        EXPECT_EQ(raw.second.width > 0, c.technique == techniqueFromName("second-depth"));
        EXPECT_EQ(raw.raw.size() > 1, c.technique == techniqueFromName("csm"));  // 8 terms: 4 layers

        RenderInputs shared;
        shared.rawMaps = first.rawMaps;
        const RenderResult second = render(s, shared);
        for (const char* image : {"final", "shadow", "moments_raw", "moments_filtered"}) {
            if (!first.images.count(image)) continue;
            ASSERT_TRUE(second.images.count(image)) << image;
            EXPECT_TRUE(sameBytes(first.images.at(image), second.images.at(image))) << image;
        }
        // The shadow passes did not run (no time), the others did.
        const PassPlan plan = planPasses(s);
        ASSERT_EQ(second.passMillis.size(), plan.passes.size());
        for (size_t i = 0; i < plan.passes.size(); ++i) {
            const bool shadow = plan.passes[i].kind == PassKind::Shadow ||
                                plan.passes[i].kind == PassKind::ShadowSecond;
            if (shadow) EXPECT_EQ(second.passMillis[i], 0.0) << toString(plan.passes[i].kind);
            else EXPECT_GT(second.passMillis[i], 0.0) << toString(plan.passes[i].kind);
        }
    }
}

TEST(RenderInputs, OneRawMapServesEveryFilterOfItsFormat) {
    // VSM's map rendered once under a Gaussian scene, then filtered by the SAT instead: the
    // same images as a VSM + SAT render that makes its own map.
    RenderInputs keep;
    keep.keepRawMaps = true;
    const RenderResult gaussian = render(smallScene(techniqueFromName("vsm"), FilterKind::Gaussian), keep);
    const Scene sat = smallScene(techniqueFromName("vsm"), FilterKind::Sat);
    RenderInputs shared;
    shared.rawMaps = gaussian.rawMaps;
    const RenderResult fromShared = render(sat, shared);
    const RenderResult own = render(sat, {});
    EXPECT_TRUE(sameBytes(fromShared.images.at("shadow"), own.images.at("shadow")));
    EXPECT_TRUE(sameBytes(fromShared.images.at("final"), own.images.at("final")));
    // msm4 and msm4-hausdorff store the same RGBA32F moments: one map serves both.
    const RenderResult msm4 = render(smallScene(techniqueFromName("msm4"), FilterKind::Gaussian), keep);
    const Scene hausdorff = smallScene(techniqueFromName("msm4-hausdorff"), FilterKind::Gaussian);
    shared.rawMaps = msm4.rawMaps;
    EXPECT_TRUE(sameBytes(render(hausdorff, shared).images.at("shadow"),
                          render(hausdorff, {}).images.at("shadow")));
}

TEST(RenderInputs, TheGivenRawMapIsWhatLightingReads) {
    // A map with nothing in it (relative depth 1 everywhere) must light everything: were the
    // shadow pass run anyway, or the given map ignored, the box would still cast its shadow.
    const Scene s = smallScene(techniqueFromName("hard"), FilterKind::None);
    RenderInputs keep;
    keep.keepRawMaps = true;
    const RenderResult normal = render(s, keep);
    double shadowed = 0;
    for (float g : normal.images.at("shadow").pixels) shadowed += g;
    ASSERT_GT(shadowed, 100.0) << "the scene must have a shadow for this test to mean something";
    RenderInputs empty;
    empty.rawMaps = normal.rawMaps;
    for (float& z : empty.rawMaps.at(0).raw.front().pixels) z = 1.0f;
    const RenderResult lit = render(s, empty);
    for (float g : lit.images.at("shadow").pixels) ASSERT_EQ(g, 0.0f);
}

TEST(RenderInputs, AMapOfTheWrongSizeOrFormatIsRefused) {
    const Scene s = smallScene(techniqueFromName("vsm"), FilterKind::Gaussian);
    RenderInputs keep;
    keep.keepRawMaps = true;
    RenderInputs wrong;
    wrong.rawMaps = render(smallScene(techniqueFromName("hard"), FilterKind::None), keep).rawMaps;  // R32F
    EXPECT_THROW(render(s, wrong), std::invalid_argument);
    wrong.rawMaps.at(0).raw.clear();
    EXPECT_THROW(render(s, wrong), std::invalid_argument);
}

}  // namespace sl
