// planPasses: only the passes the scene's effects call for, in order.
#include "pass_plan.h"

#include <gtest/gtest.h>

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

TEST(PassPlan, SatIsTwoScansAndAnOptionalResolve) {
    Scene s = sceneWith(FilterKind::Sat, 1, true);
    EXPECT_EQ(kinds(planPasses(s)),
              (std::vector<PassKind>{PassKind::Shadow, PassKind::SatRows, PassKind::SatColumns,
                                     PassKind::SatResolve, PassKind::Lighting}));
    EXPECT_EQ(kinds(planPasses(s, {.resolveSat = false})),
              (std::vector<PassKind>{PassKind::Shadow, PassKind::SatRows, PassKind::SatColumns,
                                     PassKind::Lighting}));
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
