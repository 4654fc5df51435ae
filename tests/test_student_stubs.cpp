// The student skeleton compiles, runs, and is reported stage by stage as not implemented;
// a stage is never reported once it is implemented.
#include "gl_test_support.h"
#include "stub_survey.h"

#include <fstream>

namespace sl {
namespace {

bool mentions(const std::vector<std::string>& notes, const std::string& what) {
    for (const auto& n : notes)
        if (n.find(what) != std::string::npos && n.find("not implemented yet") != std::string::npos)
            return true;
    return false;
}

}  // namespace

TEST(StudentStubs, GaussianSceneReportsMomentsBlurAndMsm) {
    RenderResult r = test::renderScene(loadScene(test::scenePath("classic")), "student");
    EXPECT_TRUE(mentions(r.stubNotes, "student/moments.glsl")) << testing::PrintToString(r.stubNotes);
    EXPECT_TRUE(mentions(r.stubNotes, "student/gaussian_blur.comp"));
    EXPECT_TRUE(mentions(r.stubNotes, "student/msm.glsl"));
    // At a glance: the final image is magenta wherever the light reaches.
    const Image& f = r.images.at("final");
    int magenta = 0;
    for (int i = 0; i < f.width * f.height; ++i)
        magenta += f.pixels[i * 3] == 1.0f && f.pixels[i * 3 + 1] == 0.0f && f.pixels[i * 3 + 2] == 1.0f;
    EXPECT_GT(magenta, f.width * f.height / 10);
}

TEST(StudentStubs, SatSceneReportsTheScanAndTheLookup) {
    RenderResult r = test::renderScene(loadScene(test::scenePath("contact")), "student");
    EXPECT_TRUE(mentions(r.stubNotes, "student/sat.comp")) << testing::PrintToString(r.stubNotes);
    EXPECT_TRUE(mentions(r.stubNotes, "student/sat_lookup.glsl"));
}

TEST(StudentStubs, OneImplementedStageIsNoLongerReported) {
    // The student's stages with moments.glsl solved: only the others remain.
    test::sharedContext();
    Renderer renderer(ShaderLibrary::mixed(test::root() / "student",
                                           {{"moments.glsl", test::root() / "reference"}},
                                           test::root()));
    Scene scene = loadScene(test::scenePath("classic"));
    RenderResult r = renderer.render(scene, planPasses(scene));
    EXPECT_FALSE(mentions(r.stubNotes, "moments.glsl")) << testing::PrintToString(r.stubNotes);
    EXPECT_TRUE(mentions(r.stubNotes, "gaussian_blur.comp"));
}

TEST(StudentStubs, SatLookupStubIsReportedOnceTheScanWorks) {
    test::sharedContext();
    Renderer renderer(ShaderLibrary::mixed(test::root() / "reference",
                                           {{"sat_lookup.glsl", test::root() / "student"}},
                                           test::root()));
    Scene scene = loadScene(test::scenePath("contact"));
    // The stub lookup shows in the filtered map, which the demo and the grader ask for.
    RenderResult r = renderer.render(scene, planPasses(scene, {.resolveSat = true}));
    EXPECT_TRUE(mentions(r.stubNotes, "sat_lookup.glsl")) << testing::PrintToString(r.stubNotes);
    EXPECT_FALSE(mentions(r.stubNotes, "sat.comp"));
}


// The list a student works down: every public scene rendered from the untouched stubs names,
// between them, all seven stage functions, each in the order a frame runs them, although the
// output of each render shows only the first stub on a path (a stub relativeDepth keeps the
// lighting from calling satKernelTexels, a stub table leaves satBoxAverage nothing to return).
TEST(StudentStubs, EveryPublicSceneNamesEveryStubFunctionItRuns) {
    test::sharedContext();
    const ShaderLibrary library = test::library("student");
    Renderer renderer(library);
    std::vector<std::string> all;
    for (const auto& e : fs::directory_iterator(test::root() / "scenes")) {
        if (e.path().extension() != ".json") continue;
        Scene scene = loadScene(e.path().string());
        const PassPlan plan = planPasses(scene);
        RenderResult r = renderer.render(scene, plan);
        completeStubNotes(library, plan, r);
        std::vector<std::string> expected;
        for (StageFunction f : functionsRun(plan))
            expected.push_back(stubNoteText(library.displayPath(library.resolve(stageFunction(f).file)), f));
        EXPECT_EQ(r.stubNotes, expected) << e.path();
        for (const auto& n : r.stubNotes)
            if (std::find(all.begin(), all.end(), n) == all.end()) all.push_back(n);
    }
    EXPECT_EQ(all.size(), kStageFunctions.size()) << testing::PrintToString(all);
    const Scene penumbra = loadScene(test::scenePath("penumbra"));
    EXPECT_EQ(functionsRun(planPasses(penumbra)).size(), 6u);  // all but the Gaussian
}

// One stub among solved stages is named, and only it: the survey probes each function alone.
TEST(StudentStubs, AStubAmongSolvedStagesIsNamedAlone) {
    if (!fs::exists(test::root() / "reference")) GTEST_SKIP() << "needs reference/";
    test::sharedContext();
    const fs::path dir = test::tempDir("stub_kernel_alone");
    std::string lookup = test::readFile(test::root() / "reference/sat_lookup.glsl");
    const size_t at = lookup.find('{', lookup.find("float satKernelTexels(sampler2D"));
    lookup.insert(at + 1, "\n    return -1.0;\n");
    test::writeFile(dir / "sat_lookup.glsl", lookup);
    const ShaderLibrary library =
        ShaderLibrary::mixed(test::root() / "reference", {{"sat_lookup.glsl", dir}}, test::root());
    EXPECT_EQ(stubFunctions(library, functionsRun(planPasses(loadScene(test::scenePath("penumbra"))))),
              std::vector<StageFunction>{StageFunction::SatKernelTexels});
    // The three SAT functions stubbed under solved moments and msm: all three named.
    const ShaderLibrary sat = ShaderLibrary::mixed(
        test::root() / "reference",
        {{"sat.comp", test::root() / "student"}, {"sat_lookup.glsl", test::root() / "student"}}, test::root());
    EXPECT_EQ(stubFunctions(sat, functionsRun(planPasses(loadScene(test::scenePath("penumbra"))))),
              (std::vector<StageFunction>{StageFunction::SatPass, StageFunction::SatBoxAverage,
                                          StageFunction::SatKernelTexels}));
    EXPECT_TRUE(stubFunctions(test::library("reference"), std::vector<StageFunction>(
        {StageFunction::RelativeDepth, StageFunction::ComputeMoments, StageFunction::GaussianPass,
         StageFunction::SatPass, StageFunction::SatBoxAverage, StageFunction::SatKernelTexels,
         StageFunction::MomentShadowIntensity})).empty());
}

}  // namespace sl
