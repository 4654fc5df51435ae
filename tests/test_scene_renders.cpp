// Every public scene renders with the reference, every shadow probe the scene's author wrote
// down holds, and no image has a NaN; each render's CPU time is printed (a benchmark's figure).
#include "gl_test_support.h"

#include "cost_clock.h"

#include <cstdio>
#include <cmath>

namespace sl {
namespace {

std::vector<std::string> publicScenes() {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(test::root() / "scenes"))
        if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace

class SceneRender : public ::testing::TestWithParam<std::string> {};

TEST_P(SceneRender, ProbesHoldAndImagesAreFinite) {
    Scene scene = loadScene(test::scenePath(GetParam()));
    test::sharedContext();
    // Its cost is printed, not asserted (speed belongs to benchmarks): the CPU time of every
    // thread, which a busy machine moves far less than the wall clock.
    const double cpuBefore = processCpuMillis();
    RenderResult r = test::renderScene(scene);
    std::printf("[scene] %s rendered in %.0f CPU ms\n", GetParam().c_str(),
                processCpuMillis() - cpuBefore);
    for (const auto& [name, image] : r.images)
        for (float v : image.pixels) ASSERT_TRUE(std::isfinite(v)) << name;
    EXPECT_TRUE(r.stubNotes.empty());
    for (const ShadowProbe& probe : scene.probes) {
        int cam = 0;
        while (cam < int(scene.cameras.size()) && scene.cameras[cam].name != probe.camera) ++cam;
        ASSERT_LT(cam, int(scene.cameras.size())) << probe.camera;
        const std::string key = cam == 0 ? "shadow" : "shadow_" + probe.camera;
        const Image& g = r.images.at(key);
        const int row = g.height - 1 - probe.pixel.y;  // probes count rows from the top
        EXPECT_NEAR(g.at(probe.pixel.x, row, 0), probe.shadow, probe.tolerance)
            << GetParam() << " pixel (" << probe.pixel.x << "," << probe.pixel.y << "): "
            << probe.why;
    }
}

INSTANTIATE_TEST_SUITE_P(Public, SceneRender, ::testing::ValuesIn(publicScenes()),
                         [](const auto& info) { return info.param; });

TEST(SceneRender, UnshadowedSceneHasNoMomentImages) {
    Scene scene = loadScene(test::scenePath("unlit_no_shadow"));
    RenderResult r = test::renderScene(scene);
    EXPECT_FALSE(r.images.count("moments_raw"));
    EXPECT_TRUE(r.images.count("final"));
    for (float v : r.images.at("shadow").pixels) ASSERT_EQ(v, 0.0f);
}

}  // namespace sl
