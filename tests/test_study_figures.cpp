// The study's figure data (study_figures.h) and its "which configuration" table (study_pick.h),
// on hand-made rows whose answers are known: a bug that reads the wrong pass, the wrong median,
// or picks outside the error band shows here.
#include "study_figures.h"
#include "study_flicker.h"
#include "study_pick.h"

#include <gtest/gtest.h>

namespace sl {
namespace {

StudyRow row(const std::string& spec, const std::string& filter, int r, int size, double rmse,
             double ratio, size_t bytes) {
    StudyRow x;
    x.scene = "contact_hardening";
    x.spec = x.technique = spec;
    x.filter = filter;
    x.radius = r;
    x.mapSize = size;
    x.truth.rmse = rmse;
    x.frameRatio = ratio;
    x.mapBytes = bytes;
    return x;
}

TEST(StudyFigures, PassGroupsTakeEachPassesMedianIntoItsGroup) {
    StudyRow r;
    r.passTimes = "shadow@L0=1.0/2.0/9.0(shared);widen@L0=0.5/0.25/1;gaussian-x@L0=3/4/5;"
                  "gaussian-y@L0=1/1.5/2;lighting=7/8/9";
    const PassGroups g = passGroups(r);
    EXPECT_DOUBLE_EQ(g.shadow, 2.0);
    EXPECT_DOUBLE_EQ(g.filter, 0.25 + 4.0 + 1.5);
    EXPECT_DOUBLE_EQ(g.lighting, 8.0);
}

TEST(StudyFigures, MarkersGrowWithTheMapAndKernelsHaveTheirOwnColours) {
    EXPECT_LT(markerSize(256), markerSize(512));
    EXPECT_LT(markerSize(1024), markerSize(2048));
    EXPECT_EQ(kernelColour("none", 0), "#000000");
    EXPECT_NE(kernelColour("gaussian", 1), kernelColour("gaussian", 4));
    EXPECT_NE(kernelColour("gaussian", 4), kernelColour("sat", 4));
    EXPECT_EQ(kernelName("sat", 4), "sat r4");
}

TEST(StudyPick, AnswersComeFromTheRowsWithinEachErrorBand) {
    const std::vector<StudyRow> rows = {
        row("msm-soft", "sat", 1, 2048, 0.0100, 9.0, 64u << 20),  // most accurate, dear
        row("msm4", "sat", 4, 512, 0.0108, 3.0, 4u << 20),        // within 10 %, cheaper
        row("msm4-16bit", "sat", 4, 512, 0.0109, 3.5, 2u << 20),  // within 10 %, fewest bytes
        row("pcf", "gaussian", 1, 256, 0.0140, 0.4, 256u << 10),  // within 50 %, cheapest
        row("hard", "none", 0, 256, 0.0300, 0.2, 256u << 10),     // cheapest of all, too far off
    };
    std::vector<const StudyRow*> ptrs;
    for (const auto& r : rows) ptrs.push_back(&r);
    const std::vector<Pick> p = pickConfigurations(ptrs);
    ASSERT_EQ(p.size(), 4u);
    EXPECT_EQ(p[0].row, &rows[0]);
    EXPECT_EQ(p[1].row, &rows[1]);
    EXPECT_EQ(p[2].row, &rows[3]);
    EXPECT_EQ(p[3].row, &rows[2]);
    const std::string md = pickMarkdown(p);
    EXPECT_NE(md.find("| contact_hardening | point | most accurate | msm-soft sat r1 2048² | 0.0100 |"),
              std::string::npos) << md;
}

}  // namespace
}  // namespace sl

namespace sl {
namespace {

TEST(StudyFlicker, TheLightTurnsAboutItsTargetAndChangeIsMeanAbsoluteOverReachedPixels) {
    Scene s;
    Light l;
    l.position = {3.0f, 5.0f, 0.0f};
    l.target = {1.0f, 0.0f, 0.0f};
    s.lights.push_back(l);
    const Scene same = movedLight(s, 0, 10.0);
    EXPECT_EQ(same.lights[0].position, l.position);
    const Scene q = movedLight(s, 9, 10.0);  // 90° about the vertical through the target
    EXPECT_NEAR(q.lights[0].position.x, 1.0f, 1e-5);
    EXPECT_NEAR(q.lights[0].position.y, 5.0f, 1e-6);
    EXPECT_NEAR(std::abs(q.lights[0].position.z), 2.0f, 1e-5);
    EXPECT_EQ(q.lights[0].target, l.target);

    Image a(2, 2, 1), b(2, 2, 1), ra(2, 2, 1, 1.0f), rb(2, 2, 1, 1.0f);
    a.pixels = {0.0f, 1.0f, 0.5f, 0.2f};
    b.pixels = {0.5f, 0.0f, 0.5f, 0.9f};
    rb.pixels[3] = 0.0f;  // not reached in b: left out
    EXPECT_NEAR(meanChange(a, b, ra, rb), (0.5 + 1.0 + 0.0) / 3.0, 1e-7);
}

}  // namespace
}  // namespace sl
