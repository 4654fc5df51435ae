// Hostile input (the same work gets the same grade on any machine): time limits. A fixed 20 s limit
// gave a 1e9-iteration render 0 on a busy machine and full marks on an idle one, and a loop in
// msm.glsl cost 20 s per scene. The limit is now kTimeoutFactor (10) x the reference's own render
// of the scene, timed on the same machine in the same run (at least kTimeoutFloor s), and a stage
// that timed out once is not run again on the other scenes, nor are the finals that run its files:
// those tests get the same reason at once.
#include "test_grader_support.h"

#include <chrono>
#include <regex>

namespace sl {

TEST(HostileTimeouts, TheLimitFollowsTheReferenceAndATimeoutIsNotRepeated) {
    // Nested loops: llvmpipe cuts each after 65 535 iterations, so this runs ~4e9 per texel.
    std::string moments = test::readFile(test::root() / "reference" / "moments.glsl");
    const std::string head = "vec4 computeMoments(float z)\n{\n";
    ASSERT_NE(moments.find(head), std::string::npos) << "the reference's function changed";
    moments.replace(moments.find(head), head.size(),
                    head + "    for (int i = 0; i < 100000; ++i)\n"
                           "        for (int j = 0; j < 100000; ++j) z = fract(z * 1.0001 + 0.1);\n");
    auto sub = test::makeSubmission("timeouts", {{"moments.glsl", moments}});
    const auto start = std::chrono::steady_clock::now();
    auto g = test::grade("--scenes classic,contact --no-report --submission " + sub.string(),
                         test::tempDir("timeouts_out"));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    // "timed out after N s (10 x the reference's R s render)"
    std::smatch m;
    const std::string first = g.output("classic", "moments");
    ASSERT_TRUE(std::regex_search(first, m, std::regex(R"(timed out after (\d+) s \((\d+) x the reference's ([0-9.]+) s render)")))
        << first;
    const double limit = std::stod(m[1]), factor = std::stod(m[2]), ref = std::stod(m[3]);
    EXPECT_EQ(factor, 10.0);  // kTimeoutFactor
    EXPECT_NEAR(limit, std::max(5.0, factor * ref), 1.0) << first;
    // contact's moments stage was not run: the same reason, and no second wait.
    const std::string second = g.output("contact", "moments");
    EXPECT_NE(second.find("timed out after"), std::string::npos) << second;
    EXPECT_NE(second.find("not run here"), std::string::npos) << second;
    EXPECT_EQ(g.score("contact", "moments"), 0.0);
    // contact's final runs moments.glsl too: not started once the moments stage timed out
    // (classic's final ran beside classic's moments render, in the same limit).
    const std::string final = g.output("contact", "final");
    EXPECT_NE(final.find("not run here: the moments stage timed out"), std::string::npos) << final;
    EXPECT_LT(seconds, 2 * limit) << "a second limit was waited for";
    EXPECT_TRUE(g.full("contact", "sat")) << g.output("contact", "sat");
    EXPECT_TRUE(g.full("classic", "msm")) << g.output("classic", "msm");
}

// A loop in gaussian_blur.comp costs the renders that compile it (the Gaussian stage, and the
// finals of Gaussian scenes) and nothing else: a SAT scene's final never runs that file, and
// a final that did not render is not read as the stages' interface failing.
TEST(HostileTimeouts, ALoopCostsOnlyTheRendersThatRunItsFile) {
    std::string blur = test::readFile(test::root() / "reference" / "gaussian_blur.comp");
    // The loop's value moves the window (as the moments test's feeds the depth): a loop whose
    // result is unused, or provably in range, may be compiled away. llvmpipe ends a loop nest
    // after 65 535 iterations in all (one counter for the nest), so each iteration does 32 steps:
    // minutes per pass, never within the limit.
    std::string steps;
    for (int k = 0; k < 32; ++k) steps += " z = fract(z * 1.0001 + 0.1);";
    const std::string anchor = "    ivec2 last = uImageSize - 1;\n";
    ASSERT_NE(blur.find(anchor), std::string::npos) << "the reference's main changed";
    blur.replace(blur.find(anchor), anchor.size(),
                 anchor + "    float z = float(uImageSize.x) * 0.001;\n"
                          "    for (int i = 0; i < 100000; ++i)\n"
                          "        for (int j = 0; j < 100000; ++j) {" + steps + " }\n"
                          "    first += ivec2(int(z * 3.0), 0);\n");
    auto sub = test::makeSubmission("gaussian_loop", {{"gaussian_blur.comp", blur}});
    // classic and depth_range: Gaussian; contact and penumbra: SAT, their finals started after
    // the Gaussian's renders have timed out.
    auto g = test::grade("--scenes classic,depth_range,contact,penumbra --no-report --submission " +
                             sub.string(),
                         test::tempDir("gaussian_loop_out"));
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    EXPECT_NE(g.output("classic", "gaussian").find("timed out after"), std::string::npos)
        << g.output("classic", "gaussian");
    EXPECT_EQ(g.score("depth_range", "final"), 0.0) << g.output("depth_range", "final");
    for (const char* scene : {"contact", "penumbra"}) {
        EXPECT_TRUE(g.full(scene, "final")) << scene << ": " << g.output(scene, "final");
        EXPECT_TRUE(g.full(scene, "sat")) << scene << ": " << g.output(scene, "sat");
    }
    EXPECT_EQ(g.run.output.find("while every isolated stage"), std::string::npos) << g.run.output;
    // The reasons say it: the loop, the render not run and why, the files a final runs; no
    // hint reads a timeout as a wrong blur.
    EXPECT_NE(g.output("depth_range", "gaussian").find("not run here: this stage timed out after"),
              std::string::npos) << g.output("depth_range", "gaussian");
    const std::string final = g.output("classic", "final");
    if (final.find("not run here") == std::string::npos)  // classic's final ran out of time itself
        EXPECT_NE(final.find("this render runs submission/moments.glsl, submission/msm.glsl, "
                             "submission/gaussian_blur.comp"), std::string::npos) << final;
    EXPECT_EQ(g.run.output.find("look at gaussian_blur.comp (weights"), std::string::npos) << g.run.output;
}

}  // namespace sl
