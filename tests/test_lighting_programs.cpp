// The renderer's warm-up (Renderer::compilePrograms) compiles the very programs a render's
// passes run: the Gaussians' with the scene's blur radius (a compile-time constant of both the
// student's and the framework's), the lighting's with the plan's slot count (SL_SHADOW_SLOTS).
// Otherwise the first pass that asks for one pays the driver's compiler in its time.
#include "gl_test_support.h"
#include "technique.h"

#include <gtest/gtest.h>

namespace sl {
namespace {

// `name` (scenes/<name>.json) made small: the programs do not depend on the sizes.
Scene warmUpScene(const std::string& name) {
    Scene s = loadScene(test::scenePath(name).string());
    s.shadow.mapSize = 128;
    for (Camera& c : s.cameras) c.width = c.height = 32;
    return s;
}

// Compiles the plan's programs, then renders: the render must compile nothing more.
void expectNoCompileAfterWarmUp(const Scene& scene) {
    test::sharedContext();
    Renderer renderer(test::library("reference"));
    const PassPlan plan = planPasses(scene);
    renderer.compilePrograms(scene, plan);
    const size_t warm = renderer.programCount();
    renderer.render(scene, plan);
    EXPECT_EQ(renderer.programCount(), warm) << scene.path;
}

}  // namespace

TEST(LightingPrograms, WarmUpCompilesTheStudentStagesPrograms) {
    expectNoCompileAfterWarmUp(warmUpScene("classic"));    // msm4, Gaussian
    expectNoCompileAfterWarmUp(warmUpScene("wide_blur"));  // msm4, SAT
}

TEST(LightingPrograms, WarmUpCompilesTheFrameworkGaussianForTheScenesRadius) {
    for (Technique t : {techniqueFromName("vsm"), techniqueFromName("csm")}) {
        Scene s = warmUpScene("classic");
        overrideTechnique(s.shadow, t);
        ASSERT_EQ(s.shadow.filter, FilterKind::Gaussian);
        for (int radius : {2, 5}) {
            s.shadow.gaussianRadius = radius;
            expectNoCompileAfterWarmUp(s);
        }
    }
}

TEST(LightingPrograms, WarmUpCompilesTheLightingForCascadesAndSeveralLights) {
    Scene cascades = loadScene((test::root() / "scenes" / "ladder" / "large_directional.json").string());
    cascades.shadow.mapSize = 128;
    for (Camera& c : cascades.cameras) c.width = c.height = 32;
    expectNoCompileAfterWarmUp(cascades);
    Scene two = warmUpScene("classic");
    two.lights.push_back(two.lights.front());
    two.lights.back().position.x += 1.0f;
    expectNoCompileAfterWarmUp(two);
}

}  // namespace sl
