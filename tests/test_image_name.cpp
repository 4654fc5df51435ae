// ImageName: every image a render makes parses and writes back to the same name; the parts
// land where the renderer put them; names no render makes are refused.
#include "gl_test_support.h"
#include "image_name.h"
#include "technique.h"

#include <gtest/gtest.h>

namespace sl {

TEST(ImageName, PartsRoundTrip) {
    const auto n = ImageName::parse("moments_raw_light2_cascade3_layer1");
    ASSERT_TRUE(n);
    EXPECT_EQ(n->kind, ImageKind::MomentsRaw);
    EXPECT_EQ(n->light, 2);
    EXPECT_EQ(n->cascade, 3);
    EXPECT_EQ(n->layer, 1);
    EXPECT_EQ(n->str(), "moments_raw_light2_cascade3_layer1");
    const auto cam = ImageName::parse("msm_shadow_overhead");
    ASSERT_TRUE(cam);
    EXPECT_EQ(cam->kind, ImageKind::Shadow);
    EXPECT_TRUE(cam->msmIsolated);
    EXPECT_EQ(cam->camera, "overhead");
    EXPECT_FALSE(isImage("msm_shadow", ImageKind::Shadow));  // the grader's, not the render's
    EXPECT_TRUE(isImage("final_overhead", ImageKind::Final));
    EXPECT_EQ(ImageName::parse("moments_raw_depth_ladder")->kind, ImageKind::DepthLadder);
    EXPECT_EQ(ImageName::parse("moments_filtered_kernel")->kind, ImageKind::SatKernel);
    EXPECT_TRUE(ImageName::parse("moments_filtered_kernel")->moments());
    EXPECT_EQ(ImageName::parse("sat_layer1")->kind, ImageKind::Sat);
    for (const char* bad : {"moments_rawx", "final_", "moments_raw_light", "depth", "sat_light1x", ""})
        EXPECT_FALSE(ImageName::parse(bad)) << bad;
}

// A scene with two cameras and CSM's layers: every image name the renderer makes reads back.
TEST(ImageName, EveryRenderedNameParsesBack) {
    Scene s = loadScene((test::root() / "scenes" / "classic.json").string());
    s.shadow.mapSize = 128;
    for (Camera& c : s.cameras) c.width = c.height = 32;
    overrideTechnique(s.shadow, techniqueFromName("csm"));
    s.shadow.filter = FilterKind::Sat;
    const RenderResult r = test::renderScene(s);
    int layers = 0, cameras = 0;
    for (const auto& [name, image] : r.images) {
        const auto n = ImageName::parse(name);
        ASSERT_TRUE(n) << name;
        EXPECT_EQ(n->str(), name);
        layers += n->layer > 0;
        cameras += !n->camera.empty();
    }
    EXPECT_GT(layers, 0) << "csm's further layers";
    EXPECT_GT(cameras, 0) << "the second camera's images";
}

}  // namespace sl
