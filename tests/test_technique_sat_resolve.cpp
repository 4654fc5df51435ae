// The techniques' SAT resolve (the solution's sat.comp and satBoxAverage, shaders/sat_resolve.comp):
// with a SAT filter and PlanOptions::resolveSat, vsm, evsm, msm4-hausdorff, ... write
// moments_filtered, the box mean the lighting reads from the table at every texel centre, one
// RGBA32F layer at a time. Checked against an independent CPU oracle: the coverage-weighted
// mean of moments_raw over the same box, in double, straight from the definition (no table).
#include "gl_test_support.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace sl {
namespace {

Scene satScene(Technique t, float kernel) {
    Scene s = loadScene((test::root() / "scenes" / "ladder" / "box_on_plane.json").string());
    overrideTechnique(s.shadow, t);
    s.shadow.filter = FilterKind::Sat;
    s.shadow.mapSize = 128;
    s.shadow.satKernelTexels = kernel;
    for (Camera& c : s.cameras) c.width = 64, c.height = 48;
    return s;
}

// Overlap of [a, b] with texel [i, i + 1].
double coverage(double a, double b, int i) {
    return std::max(0.0, std::min(b, i + 1.0) - std::max(a, double(i)));
}

// Mean of `raw` over the box of `kernel` texels centred on texel (x, y)'s centre, clipped to
// the map, partial texels weighted by their covered area (docs/techniques.md, "sat").
double boxMean(const Image& raw, int x, int y, int c, double kernel) {
    const double cx = x + 0.5, cy = y + 0.5;
    const double x0 = std::clamp(cx - kernel / 2, 0.0, double(raw.width));
    const double x1 = std::clamp(cx + kernel / 2, 0.0, double(raw.width));
    const double y0 = std::clamp(cy - kernel / 2, 0.0, double(raw.height));
    const double y1 = std::clamp(cy + kernel / 2, 0.0, double(raw.height));
    double sum = 0.0;
    for (int j = int(std::floor(y0)); j < int(std::ceil(y1)); ++j)
        for (int i = int(std::floor(x0)); i < int(std::ceil(x1)); ++i)
            sum += coverage(x0, x1, i) * coverage(y0, y1, j) * raw.at(i, j, c);
    return sum / ((x1 - x0) * (y1 - y0));
}

}  // namespace

TEST(TechniqueSatResolve, PlanAddsTheResolveOnlyWhenAsked) {
    const Scene s = satScene(techniqueFromName("vsm"), 7.0f);
    const PassPlan with = planPasses(s, {.resolveSat = true});
    ASSERT_NE(with.texture(0, TextureRole::Filtered), nullptr);
    EXPECT_EQ(with.texture(0, TextureRole::Filtered)->format, "RGBA32F");  // the filter stages' format
    EXPECT_EQ(with.passes[3].kind, PassKind::SatResolve);
    const PassPlan without = planPasses(s);
    EXPECT_EQ(without.texture(0, TextureRole::Filtered), nullptr);
    for (const PlannedPass& p : without.passes) EXPECT_NE(p.kind, PassKind::SatResolve);
}

TEST(TechniqueSatResolve, FilteredMapIsTheBoxMeanOfTheRawMap) {
    // Tolerance: the reference's table errs by at most ~7e-6 of the largest value in the map
    // (docs/numerics.md: tiles of offset sums; EVSM's warped values span e^±40, so there the
    // largest value sets the scale), and the result is rounded to float32. Allowed: 3e-5 of the
    // channel's largest |value| + 1e-6 relative; a box off by half a texel errs by about a
    // texel's value / kernel at every shadow edge, far more.
    for (Technique t : {techniqueFromName("vsm"), techniqueFromName("evsm4"), techniqueFromName("msm4-hausdorff")})
        for (float kernel : {7.0f, 4.5f}) {
            SCOPED_TRACE(techniqueRow(t).name + " kernel " + std::to_string(kernel));
            const RenderResult r = test::renderScene(satScene(t, kernel));
            ASSERT_TRUE(r.images.count("moments_filtered"));
            const Image& raw = r.images.at("moments_raw");
            const Image& filtered = r.images.at("moments_filtered");
            ASSERT_EQ(filtered.channels, raw.channels);
            std::vector<double> largest(raw.channels, 0.0);
            for (int y = 0; y < raw.height; ++y)
                for (int x = 0; x < raw.width; ++x)
                    for (int c = 0; c < raw.channels; ++c)
                        largest[c] = std::max(largest[c], std::abs(double(raw.at(x, y, c))));
            double worst = 0.0, spread = 0.0;
            for (int y = 0; y < raw.height; ++y)
                for (int x = 0; x < raw.width; ++x)
                    for (int c = 0; c < raw.channels; ++c) {
                        const double want = boxMean(raw, x, y, c, kernel);
                        const double allowed = 1e-7 + 3e-5 * largest[c] + 1e-6 * std::abs(want);
                        worst = std::max(worst, std::abs(filtered.at(x, y, c) - want) / allowed);
                        spread = std::max(spread, std::abs(raw.at(x, y, c) - want));
                    }
            EXPECT_LE(worst, 1.0) << "worst error in units of the allowance";
            // The box really averages something (a map of constants would pass any box).
            EXPECT_GT(spread, 1e-3);
        }
}

TEST(TechniqueSatResolve, ResolveChangesNoLighting) {
    // The resolve is an output only: the lit image is the same with and without it.
    const Scene s = satScene(techniqueFromName("vsm"), 7.0f);
    test::sharedContext();
    Renderer renderer(test::library("reference"));
    const Image with = renderer.render(s, planPasses(s, {.resolveSat = true})).images.at("shadow");
    const Image without = renderer.render(s, planPasses(s)).images.at("shadow");
    EXPECT_EQ(with.pixels, without.pixels);
}

}  // namespace sl
