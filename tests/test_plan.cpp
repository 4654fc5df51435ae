// planPasses: only the passes the scene's effects call for, in order.
#include "pass_plan.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace sl {
namespace {

Scene sceneWith(FilterKind filter, int lights, bool shadows, int cameras = 1) {
    Scene s;
    s.name = "plan";
    for (int i = 0; i < cameras; ++i) {
        Camera c;
        c.name = i == 0 ? "main" : "cam" + std::to_string(i);
        s.cameras.push_back(c);
    }
    for (int i = 0; i < lights; ++i) {
        Light l;
        l.castsShadows = shadows;
        s.lights.push_back(l);
    }
    s.objects.emplace_back();  // a caster: without one no light gets a map
    s.shadow.filter = filter;
    return s;
}

std::vector<PassKind> kinds(const PassPlan& plan) {
    std::vector<PassKind> out;
    for (const auto& p : plan.passes) out.push_back(p.kind);
    return out;
}

}  // namespace

TEST(PassPlan, NoShadowingLightMeansNoShadowPass) {
    PassPlan plan = planPasses(sceneWith(FilterKind::Gaussian, 1, false));
    EXPECT_EQ(kinds(plan), std::vector<PassKind>{PassKind::Lighting});
    EXPECT_EQ(plan.momentChannels, 0);
    EXPECT_TRUE(plan.shadowLights.empty());
}

TEST(PassPlan, FilterNoneDispatchesNothing) {
    PassPlan plan = planPasses(sceneWith(FilterKind::None, 1, true));
    EXPECT_EQ(kinds(plan), (std::vector<PassKind>{PassKind::Shadow, PassKind::Lighting}));
}

TEST(PassPlan, GaussianIsTwoSeparablePasses) {
    PassPlan plan = planPasses(sceneWith(FilterKind::Gaussian, 1, true));
    EXPECT_EQ(kinds(plan), (std::vector<PassKind>{PassKind::Shadow, PassKind::GaussianX,
                                                  PassKind::GaussianY, PassKind::Lighting}));
    EXPECT_EQ(plan.momentChannels, 4);  // MSM stores (z, z², z³, z⁴)
}

TEST(PassPlan, SatIsTwoScansAndAResolveOnlyWhenAsked) {
    Scene s = sceneWith(FilterKind::Sat, 1, true);
    const PassPlan plain = planPasses(s);
    EXPECT_EQ(kinds(plain), (std::vector<PassKind>{PassKind::Shadow, PassKind::SatRows,
                                                   PassKind::SatColumns, PassKind::Lighting}));
    EXPECT_EQ(plain.texture(0, TextureRole::Filtered), nullptr);
    const std::string text = explainPlan(s, plain);
    EXPECT_NE(text.find("left out: sat-resolve"), std::string::npos) << text;
    EXPECT_EQ(kinds(planPasses(s, {.resolveSat = true})),
              (std::vector<PassKind>{PassKind::Shadow, PassKind::SatRows, PassKind::SatColumns,
                                     PassKind::SatResolve, PassKind::Lighting}));
}

// A light over a scene where nothing casts shadows would render an empty map and filter it.
TEST(PassPlan, NoCasterMeansNoShadowMap) {
    Scene s = sceneWith(FilterKind::Gaussian, 2, true);
    Object ground;
    ground.castsShadows = false;
    s.objects = {ground, ground};
    PassPlan plan = planPasses(s);
    EXPECT_EQ(kinds(plan), std::vector<PassKind>{PassKind::Lighting});
    EXPECT_TRUE(plan.shadowLights.empty());
    EXPECT_EQ(plan.bytes(), 0u);
    const std::string text = explainPlan(s, plan);
    EXPECT_NE(text.find("left out: light 0: no object casts shadows"), std::string::npos) << text;
    EXPECT_NE(text.find("left out: light 1: no object casts shadows"), std::string::npos) << text;
    s.objects[1].castsShadows = true;  // one caster is enough
    EXPECT_EQ(planPasses(s).shadowLights, (std::vector<int>{0, 1}));
}

// A filter that changes no texel plans no pass: a Gaussian of radius 0.
TEST(PassPlan, AFilterThatChangesNothingIsLeftOut) {
    Scene s = sceneWith(FilterKind::Gaussian, 1, true);
    s.shadow.gaussianRadius = 0;
    PassPlan plan = planPasses(s);
    EXPECT_EQ(kinds(plan), (std::vector<PassKind>{PassKind::Shadow, PassKind::Lighting}));
    EXPECT_EQ(plan.effect.filter, FilterKind::None);
    EXPECT_EQ(std::count(plan.defines.begin(), plan.defines.end(), "SL_FILTER_GAUSSIAN"), 0);
    EXPECT_NE(explainPlan(s, plan).find("left out: gaussian filter of radius 0"),
              std::string::npos);
    s.shadow.gaussianRadius = 1;
    EXPECT_EQ(planPasses(s).passes.size(), 4u);

    // VSM keeps two channels when nothing filters its map.
    s.shadow.gaussianRadius = 0;
    s.shadow.technique = techniqueFromName("vsm");
    EXPECT_EQ(planPasses(s).texture(0, TextureRole::Raw)->format, "RG32F");
    // A SAT box of one texel keeps its table: the bilinear read that would stand in for it
    // is weighed with 8 bits on llvmpipe, not the same image.
    s.shadow.technique = techniqueFromName("msm4");
    s.shadow.filter = FilterKind::Sat;
    s.shadow.satKernelTexels = 1.0f;
    EXPECT_EQ(planPasses(s).passes.size(), 4u);
}

TEST(PassPlan, KernelReachesTheImageUnlessThePixelPicksIt) {
    ShadowEffect fx;
    fx.filter = FilterKind::Sat;
    EXPECT_TRUE(kernelReachesImage(fx));  // msm4
    fx.technique = techniqueFromName("msm-soft");
    EXPECT_FALSE(kernelReachesImage(fx));
    fx.technique = techniqueFromName("pcf");  // its PCF kernel
    EXPECT_TRUE(kernelReachesImage(fx));
    fx.filter = FilterKind::None;
    EXPECT_FALSE(kernelReachesImage(fx));
}

TEST(PassPlan, StaticLightIsRenderedOnceForSeveralCameras) {
    PassPlan plan = planPasses(sceneWith(FilterKind::Gaussian, 1, true, 3));
    int shadow = 0, lighting = 0;
    for (const auto& p : plan.passes) {
        shadow += p.kind == PassKind::Shadow;
        lighting += p.kind == PassKind::Lighting;
    }
    EXPECT_EQ(shadow, 1);
    EXPECT_EQ(lighting, 3);
}

TEST(PassPlan, EachShadowingLightGetsItsOwnMap) {
    Scene s = sceneWith(FilterKind::None, 3, true);
    s.lights[1].castsShadows = false;
    PassPlan plan = planPasses(s);
    EXPECT_EQ(plan.shadowLights, (std::vector<int>{0, 2}));
}

TEST(PassPlan, ExplainListsEveryPassWithItsTime) {
    Scene s = sceneWith(FilterKind::Gaussian, 1, true);
    PassPlan plan = planPasses(s);
    std::vector<double> ms = {1.5, 2.25, 3.0, 4.0};
    std::string text = explainPlan(s, plan, &ms);
    EXPECT_NE(text.find("gaussian-x"), std::string::npos) << text;
    EXPECT_NE(text.find("2.25 ms"), std::string::npos) << text;
    EXPECT_NE(text.find("10.75 ms"), std::string::npos) << text;  // the total
}

}  // namespace sl

// --- The technique ladder: what each row plans (expected values from the
// technique table's intent, written out here, not read from the table under test). ---
namespace sl {
namespace {

struct Expected {
    Technique technique;
    FilterKind filter;
    std::vector<PassKind> passes;  // for one light, one camera
    std::string rawFormat;
    int rawLayers;
    size_t rawBytesPerTexel;       // per layer
    size_t totalBytesPerTexel;     // every shadow texture of the light, per map texel
    int channels;
};

using K = PassKind;
const std::vector<Expected> kLadder = {
    {techniqueFromName("hard"), FilterKind::None, {K::Shadow, K::Lighting}, "R32F", 1, 4, 4 + 4, 1},
    {techniqueFromName("second-depth"), FilterKind::None, {K::Shadow, K::ShadowSecond, K::Lighting}, "R32F", 1,
     4, 4 + 4 + 4, 1},
    {techniqueFromName("pcf"), FilterKind::Gaussian, {K::Shadow, K::Lighting}, "R32F", 1, 4, 8, 1},
    {techniqueFromName("pcf"), FilterKind::Sat, {K::Shadow, K::Lighting}, "R32F", 1, 4, 8, 1},
    {techniqueFromName("pcss"), FilterKind::None, {K::Shadow, K::Lighting}, "R32F", 1, 4, 8, 1},
    // Gaussian: raw + scratch + filtered; SAT: raw + scratch + table (both twice the map's
    // width: two texels per entry), and the resolve's filtered map (output only, asked for
    // here: PlanOptions::resolveSat). A map a filter stage reads is
    // RGBA32F (the stage contract's format), so VSM's two channels fill half of each texel.
    {techniqueFromName("vsm"), FilterKind::Gaussian, {K::Shadow, K::GaussianX, K::GaussianY, K::Lighting},
     "RGBA32F", 1, 16, 4 + 3 * 16, 2},
    {techniqueFromName("vsm"), FilterKind::Sat,
     {K::Shadow, K::SatRows, K::SatColumns, K::SatResolve, K::Lighting}, "RGBA32F", 1, 16,
     4 + 2 * 16 + 2 * 32, 2},
    {techniqueFromName("vsm"), FilterKind::None, {K::Shadow, K::Lighting}, "RG32F", 1, 8, 4 + 8, 2},
    {techniqueFromName("evsm2"), FilterKind::Gaussian, {K::Shadow, K::GaussianX, K::GaussianY, K::Lighting},
     "RGBA32F", 1, 16, 4 + 48, 2},
    {techniqueFromName("evsm4"), FilterKind::Gaussian, {K::Shadow, K::GaussianX, K::GaussianY, K::Lighting},
     "RGBA32F", 1, 16, 4 + 48, 4},
    // CSM, M = 8 terms (the default): 16 channels in four RGBA32F maps, each filtered.
    {techniqueFromName("csm"), FilterKind::Gaussian, {K::Shadow, K::GaussianX, K::GaussianY, K::Lighting},
     "RGBA32F", 4, 16, 4 + 3 * 64, 16},
    // msm4 = the student stages: SAT rows, columns, and the resolve for output. The table and
    // the row pass's scratch have two RGBA32F texels per map texel.
    {techniqueFromName("msm4"), FilterKind::Sat,
     {K::Shadow, K::SatRows, K::SatColumns, K::SatResolve, K::Lighting}, "RGBA32F", 1, 16,
     4 + 2 * 16 + 2 * 32, 4},
    {techniqueFromName("msm4"), FilterKind::Gaussian, {K::Shadow, K::GaussianX, K::GaussianY, K::Lighting},
     "RGBA32F", 1, 16, 4 + 48, 4},
    {techniqueFromName("msm4-hausdorff"), FilterKind::Gaussian,
     {K::Shadow, K::GaussianX, K::GaussianY, K::Lighting}, "RGBA32F", 1, 16, 4 + 48, 4},
    // 16 bits: half of msm4's map, widened to RGBA32F for the filter stages.
    {techniqueFromName("msm4-16bit"), FilterKind::Gaussian,
     {K::Shadow, K::Widen, K::GaussianX, K::GaussianY, K::Lighting}, "RGBA16", 1, 8,
     4 + 8 + 3 * 16, 4},
    {techniqueFromName("msm4-16bit"), FilterKind::Sat,
     {K::Shadow, K::Widen, K::SatRows, K::SatColumns, K::SatResolve, K::Lighting}, "RGBA16", 1, 8,
     4 + 8 + 2 * 16 + 2 * 32, 4},
    {techniqueFromName("msm4-16bit"), FilterKind::None, {K::Shadow, K::Lighting}, "RGBA16", 1, 8, 4 + 8, 4},
    {techniqueFromName("msm-soft"), FilterKind::Sat,
     {K::Shadow, K::SatRows, K::SatColumns, K::SatResolve, K::Lighting}, "RGBA32F", 1, 16,
     4 + 2 * 16 + 2 * 32, 4},
};

}  // namespace

TEST(PassPlan, EveryTechniquePlansItsPassesFormatsAndBytes) {
    for (const Expected& e : kLadder) {
        Scene s = sceneWith(e.filter, 1, true);
        s.shadow.technique = e.technique;
        s.shadow.mapSize = 256;
        const std::string what = std::string(toString(e.technique)) + "/" + toString(e.filter);
        PassPlan plan = planPasses(s, {.resolveSat = true});  // every image, the resolve's too
        EXPECT_EQ(kinds(plan), e.passes) << what;
        const PlannedTexture* raw = plan.texture(0, TextureRole::Raw);
        ASSERT_NE(raw, nullptr) << what;
        EXPECT_EQ(raw->format, e.rawFormat) << what;
        EXPECT_EQ(raw->layers, e.rawLayers) << what;
        EXPECT_EQ(raw->bytes, 256u * 256u * e.rawBytesPerTexel * e.rawLayers) << what;
        EXPECT_EQ(plan.bytes(0), 256u * 256u * e.totalBytesPerTexel) << what;
        EXPECT_EQ(plan.momentChannels, e.channels) << what;
    }
}

// The plan names each pass's program and the roles it reads; the renderer runs just that.
TEST(PassPlan, EachPassCarriesItsProgramAndTheRolesItReads) {
    using Roles = std::vector<TextureRole>;
    const PassPlan g = planPasses(sceneWith(FilterKind::Gaussian, 1, true));
    ASSERT_EQ(g.passes.size(), 4u);
    EXPECT_EQ(g.passes[0].program.fragment, "techniques/store.frag");
    EXPECT_EQ(g.passes[0].program.defines, g.defines);
    EXPECT_EQ(g.passes[1].program.vertexOrCompute, "gaussian_blur.comp");
    EXPECT_EQ(g.passes[1].program.defines,
              std::vector<std::string>{"SL_BLUR_RADIUS=" + std::to_string(g.effect.gaussianRadius)});
    EXPECT_EQ(g.passes[1].reads, Roles{TextureRole::Raw});  // RGBA32F already: no widen
    EXPECT_EQ(g.passes[2].reads, Roles{TextureRole::Scratch});
    EXPECT_EQ(g.passes[3].program.fragment, "lighting.frag");
    EXPECT_EQ(g.passes[3].program.defines.back(), "SL_SHADOW_SLOTS=1");
    EXPECT_EQ(g.passes[3].reads, Roles{TextureRole::Filtered});

    Scene s = sceneWith(FilterKind::Sat, 2, true);
    s.shadow.technique = techniqueFromName("msm4-16bit");
    const PassPlan sat = planPasses(s);
    for (const PlannedPass& p : sat.passes) {
        if (p.kind == PassKind::SatRows) EXPECT_EQ(p.reads, Roles{TextureRole::Wide});
        if (p.kind == PassKind::Widen) EXPECT_EQ(p.program.vertexOrCompute, "widen.comp");
        if (p.kind == PassKind::Lighting) {
            EXPECT_EQ(p.reads, Roles{TextureRole::Sat});
            EXPECT_EQ(p.program.defines.back(), "SL_SHADOW_SLOTS=2");
        }
    }
    s = sceneWith(FilterKind::None, 1, true);
    s.shadow.technique = techniqueFromName("second-depth");
    const PassPlan peel = planPasses(s);
    EXPECT_EQ(peel.passes.back().reads, (Roles{TextureRole::Raw, TextureRole::Second}));
    // The shadow passes bind from roles too: the peel reads the first surface and both draw
    // with the light's depth buffer; a compute pass has none.
    ASSERT_EQ(peel.passes[1].kind, PassKind::ShadowSecond);
    EXPECT_EQ(peel.passes[0].writes, TextureRole::Raw);
    EXPECT_EQ(peel.passes[0].depth, TextureRole::Depth);
    EXPECT_EQ(peel.passes[1].reads, Roles{TextureRole::Raw});
    EXPECT_EQ(peel.passes[1].writes, TextureRole::Second);
    EXPECT_EQ(peel.passes[1].depth, TextureRole::Depth);
    EXPECT_FALSE(g.passes[1].depth.has_value());
    EXPECT_EQ(g.passes[3].depth, TextureRole::CameraDepth);
}

// --explain shows what each pass compiled and binds, from the plan.
TEST(PassPlan, ExplainPrintsEachPassesProgramAndRoles) {
    Scene s = sceneWith(FilterKind::Gaussian, 1, true);
    const PassPlan plan = planPasses(s);
    const std::string text = explainPlan(s, plan);
    EXPECT_NE(text.find("program scene.vert + techniques/store.frag [" + plan.defines.front()),
              std::string::npos) << text;
    EXPECT_NE(text.find("; reads -; writes raw, depth"), std::string::npos) << text;
    EXPECT_NE(text.find("program gaussian_blur.comp [SL_BLUR_RADIUS=" +
                        std::to_string(plan.effect.gaussianRadius) + "]; reads raw; writes scratch"),
              std::string::npos) << text;
    EXPECT_NE(text.find("reads scratch; writes filtered"), std::string::npos) << text;
    EXPECT_NE(text.find("lighting.frag ["), std::string::npos) << text;
    EXPECT_NE(text.find("SL_SHADOW_SLOTS=1]; reads filtered; writes color, shadow, camera-depth"), std::string::npos) << text;
}

TEST(PassPlan, Msm16bitHalvesTheMapOfMsm4) {
    Scene s = sceneWith(FilterKind::Gaussian, 1, true);
    s.shadow.technique = techniqueFromName("msm4");
    const size_t full = planPasses(s).texture(0, TextureRole::Raw)->bytes;
    s.shadow.technique = techniqueFromName("msm4-16bit");
    EXPECT_EQ(planPasses(s).texture(0, TextureRole::Raw)->bytes * 2, full);
}

TEST(PassPlan, CsmTermsDecideTheLayers) {
    Scene s = sceneWith(FilterKind::None, 1, true);
    s.shadow.technique = techniqueFromName("csm");
    for (int m : {1, 2, 3, 8}) {
        s.shadow.parameters["terms"] = m;
        PassPlan plan = planPasses(s);
        EXPECT_EQ(plan.texture(0, TextureRole::Raw)->layers, (m + 1) / 2) << m;
        EXPECT_EQ(plan.momentChannels, 2 * m) << m;
    }
}

TEST(PassPlan, AnUnlitSceneAllocatesAndDispatchesNothingForEveryTechnique) {
    for (const Expected& e : kLadder) {
        Scene s = sceneWith(e.filter, 2, false);
        s.shadow.technique = e.technique;
        PassPlan plan = planPasses(s);
        EXPECT_EQ(kinds(plan), std::vector<PassKind>{PassKind::Lighting});
        EXPECT_EQ(plan.bytes(), 0u);
        EXPECT_EQ(plan.momentChannels, 0);
    }
}

TEST(PassPlan, ExplainNamesFormatMemoryAndParameters) {
    Scene s = sceneWith(FilterKind::Gaussian, 1, true);
    s.shadow.technique = techniqueFromName("vsm");
    s.shadow.mapSize = 512;
    std::string text = explainPlan(s, planPasses(s));
    EXPECT_NE(text.find("technique vsm"), std::string::npos) << text;
    EXPECT_NE(text.find("RGBA32F"), std::string::npos) << text;
    EXPECT_NE(text.find("4.00 MiB"), std::string::npos) << text;  // 512² × 16 bytes (filtered)
    s.shadow.filter = FilterKind::None;
    text = explainPlan(s, planPasses(s));
    EXPECT_NE(text.find("RG32F"), std::string::npos) << text;
    EXPECT_NE(text.find("2.00 MiB"), std::string::npos) << text;  // 512² × 8 bytes
    EXPECT_NE(text.find("bleedReduction=0.18"), std::string::npos) << text;
}

}  // namespace sl
