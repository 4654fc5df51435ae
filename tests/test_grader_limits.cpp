// The grader's limits and intake (docs/grading.md): a hang, a compile error, a crash or a
// missing or refused file costs the stages that use the file, with a message that says why,
// and every other stage is still graded.
#include "test_grader_support.h"

#include <regex>

namespace sl {
namespace {

// The reference msm.glsl with its function renamed, and `body` as the graded function.
std::string msmWith(const std::string& body) {
    std::string ref = test::readFile(test::root() / "reference" / "msm.glsl");
    ref = std::regex_replace(ref, std::regex(R"(float\s+momentShadowIntensity\s*\()"),
                             "float referenceShadowIntensity(");
    return ref + "\nfloat momentShadowIntensity(vec4 b, float zf)\n{\n" + body + "\n}\n";
}

}  // namespace

TEST(GraderLimits, InfiniteLoopInMsmTimesOutAndCostsOnlyItsStages) {
    // uMomentBias < 1 always holds, but the compiler cannot know it.
    auto sub = test::makeSubmission(
        "loop", {{"msm.glsl", msmWith("    float x = zf;\n    while (uMomentBias < 1.0) x = x * 0.5 + b.x;\n"
                                      "    return clamp(x, 0.0, 1.0) * referenceShadowIntensity(b, zf);")}});
    auto g = test::grade("--timeout 3 --scenes classic --no-report --submission " + sub.string(),
                         test::tempDir("grader_loop_out"));
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    EXPECT_EQ(g.score("classic", "msm"), 0.0);
    EXPECT_NE(g.output("classic", "msm").find("timed out after 3 s"), std::string::npos)
        << g.output("classic", "msm");
    EXPECT_EQ(g.score("classic", "final"), 0.0);  // end to end uses msm.glsl too
    EXPECT_TRUE(g.full("classic", "moments")) << g.output("classic", "moments");
    EXPECT_TRUE(g.full("classic", "gaussian")) << g.output("classic", "gaussian");
}

TEST(GraderLimits, CompileErrorNamesTheStudentsFileAndLine) {
    std::string msm = test::readFile(test::root() / "reference" / "msm.glsl");
    const int lines = int(std::count(msm.begin(), msm.end(), '\n'));
    auto sub = test::makeSubmission("compile", {{"msm.glsl", msm + "this is not glsl;\n"}});
    auto g = test::grade("--scenes contact --no-report --submission " + sub.string(),
                         test::tempDir("grader_compile_out"));
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    const std::string where = "submission/msm.glsl:" + std::to_string(lines + 1);
    for (const char* stage : {"msm", "final"}) {
        EXPECT_EQ(g.score("contact", stage), 0.0);
        EXPECT_NE(g.output("contact", stage).find("compile or link error"), std::string::npos);
        EXPECT_NE(g.output("contact", stage).find(where), std::string::npos)
            << "expected " << where << " in\n" << g.output("contact", stage);
        // The first line (the score table's, the report's list of tests) names them too.
        EXPECT_EQ(g.output("contact", stage).rfind("compile or link error: " + where + ":", 0), 0u)
            << g.output("contact", stage);
        EXPECT_NE(g.run.output.find("contact: compile or link error: " + where + ":"), std::string::npos)
            << g.run.output;
    }
    EXPECT_TRUE(g.full("contact", "moments"));
    EXPECT_TRUE(g.full("contact", "sat")) << g.output("contact", "sat");
}

TEST(GraderLimits, CrashAndMissingFilesAreReportedPerStage) {
    // Only moments.glsl and gaussian_blur.comp; the gaussian worker is made to crash.
    auto sub = test::makeSubmission("crash", {}, {"sat.comp", "sat_lookup.glsl", "msm.glsl"});
    auto g = test::grade("--scenes classic,contact --no-report --submission " + sub.string(),
                         test::tempDir("grader_crash_out"), "SHADOWLAB_GRADER_FAULT=gaussian");
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    EXPECT_EQ(g.score("classic", "gaussian"), 0.0);
    EXPECT_NE(g.output("classic", "gaussian").find("crashed: SIGSEGV"), std::string::npos)
        << g.output("classic", "gaussian");
    for (const char* stage : {"msm", "final"})
        EXPECT_NE(g.output("classic", stage).find("msm.glsl: not submitted"), std::string::npos)
            << g.output("classic", stage);
    EXPECT_NE(g.output("contact", "sat").find("not submitted"), std::string::npos);
    EXPECT_TRUE(g.full("classic", "moments"));
    EXPECT_TRUE(g.full("contact", "moments"));
}

TEST(GraderLimits, IntakeRefusesSymlinksOversizedFilesAndIncludePaths) {
    auto sub = test::makeSubmission("intake", {}, {"msm.glsl"});
    fs::create_symlink(test::root() / "reference" / "msm.glsl", sub / "msm.glsl");
    std::ofstream(sub / "gaussian_blur.comp", std::ios::app) << "//" << std::string(300 * 1024, 'x') << "\n";
    std::ofstream(sub / "sat_lookup.glsl", std::ios::app) << "#include \"../../etc/passwd\"\n";
    auto g = test::grade("--scenes classic,contact --no-report --submission " + sub.string(),
                         test::tempDir("grader_intake_out"));
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    EXPECT_NE(g.output("classic", "msm").find("symbolic link"), std::string::npos)
        << g.output("classic", "msm");
    EXPECT_NE(g.output("classic", "gaussian").find("256 KiB"), std::string::npos)
        << g.output("classic", "gaussian");
    EXPECT_NE(g.output("contact", "sat").find("is a path"), std::string::npos)
        << g.output("contact", "sat");
    for (const char* s : {"msm", "gaussian", "final"}) EXPECT_EQ(g.score("classic", s), 0.0);
    EXPECT_TRUE(g.full("classic", "moments"));
}

}  // namespace sl

namespace sl {

TEST(GraderLimits, NanInTheOutputCountsAsWrongAndIsReported) {
    auto sub = test::makeSubmission(
        "nan", {{"msm.glsl", msmWith("    float zero = b.x - b.x;\n"
                                     "    return zf > 0.3 ? zero / zero : referenceShadowIntensity(b, zf);")}});
    auto g = test::grade("--scenes classic --no-report --submission " + sub.string(),
                         test::tempDir("grader_nan_out"));
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    EXPECT_LT(g.score("classic", "msm"), g.maxScore("classic", "msm"));
    EXPECT_NE(g.output("classic", "msm").find("NaN/Inf"), std::string::npos) << g.output("classic", "msm");
    EXPECT_TRUE(g.full("classic", "moments"));
}

}  // namespace sl
