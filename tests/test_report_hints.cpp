// What the failures look like (grader/output/report_diagnosis.h): each hint fits its evidence.
// A broken copy of the reference that should get a hint gets it, and one that should not does
// not: a float SAT table fails along the map's far edges, where its sums are largest, which is
// no border rule; a real border bug fails along the edges through texel (0, 0) too; a kernel
// that is wrong while every box average passes is satKernelTexels, not the table.
#include "test_grader_support.h"

namespace sl {
namespace {

std::string findings(const std::string& name, const std::map<std::string, std::string>& files,
                     const std::string& scenes) {
    const fs::path sub = test::makeSubmission("hints_" + name, files);
    auto g = test::grade("--reference golden --no-report --scenes " + scenes + " --submission " +
                             sub.string(),
                         test::tempDir("hints_" + name + "_out"));
    EXPECT_EQ(g.run.exitCode, 0) << g.run.output;
    const auto at = g.run.output.find("what the failures look like");
    EXPECT_NE(at, std::string::npos) << g.run.output;
    return at == std::string::npos ? "" : g.run.output.substr(at);
}

std::string submitted(const std::string& path) {
    return test::readFile(test::root() / "tests/submissions" / path);
}

}  // namespace

TEST(ReportHints, AFloatRunningSumIsPrecisionNotTheBorderRule) {
    // The reference's one walk per line, with its running sum in float instead of double.
    std::string sat = test::readFile(test::root() / "reference/sat.comp");
    for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
             {"    dvec4 S = dvec4(0.0);", "    vec4 S = vec4(0.0);"},
             {"S += loadEntry(alongRows, line, i);", "S += vec4(loadEntry(alongRows, line, i));"},
             {"ivec2(line, i), S);", "ivec2(line, i), dvec4(S));"}}) {
        ASSERT_NE(sat.find(from), std::string::npos) << "the reference's sat.comp changed: " << from;
        sat.replace(sat.find(from), from.size(), to);
    }
    const std::string text = findings("float_sum", {{"sat.comp", sat}}, "penumbra,sun_penumbra");
    EXPECT_NE(text.find("penumbra (sat, moments_filtered_kernel)"), std::string::npos) << text;
    EXPECT_NE(text.find("where the table's sums are largest"), std::string::npos) << text;
    EXPECT_NE(text.find("float sum"), std::string::npos) << text;
    EXPECT_EQ(text.find("check the border rule"), std::string::npos) << text;
    EXPECT_EQ(text.find("Only the per-pixel box widths"), std::string::npos) << text;
}

TEST(ReportHints, AZeroBorderBugIsTheBorderRuleNotPrecision) {
    const std::string text =
        findings("no_zero_border",
                 {{"sat.comp", submitted("sat_base/sat.comp")},
                  {"sat_lookup.glsl", submitted("mutants/sat_lookup_no_zero_border/sat_lookup.glsl")}},
                 "contact");
    EXPECT_NE(text.find("check the border rule"), std::string::npos) << text;
    EXPECT_EQ(text.find("float sum"), std::string::npos) << text;
}

TEST(ReportHints, WrongBoxWidthsWithRightAveragesNameTheKernelNotTheTable) {
    const std::string text =
        findings("no_zb_clamp",
                 {{"sat.comp", submitted("sat_base/sat.comp")},
                  {"sat_lookup.glsl", submitted("mutants/sat_kernel_no_zb_clamp/sat_lookup.glsl")}},
                 "penumbra,classic");
    EXPECT_NE(text.find("satKernelTexels"), std::string::npos) << text;
    EXPECT_NE(text.find("z_b clamped to [0, z_r]"), std::string::npos) << text;
    EXPECT_EQ(text.find("the table's precision"), std::string::npos) << text;
    EXPECT_EQ(text.find("float sum"), std::string::npos) << text;
}

// Hard cases at depths 0 and 1 fail without the guards, not without the bias: the guards are
// named there, and the bias where the bias alone is missing.
TEST(ReportHints, MissingGuardsAreNamedAsGuardsAndAMissingBiasAsTheBias) {
    const std::string guards =
        findings("unguarded", {{"msm.glsl", submitted("fragile/unguarded/msm.glsl")}}, "classic");
    EXPECT_NE(guards.find("the guards look missing"), std::string::npos) << guards;
    EXPECT_EQ(guards.find("the moment bias looks missing"), std::string::npos) << guards;
    const std::string bias =
        findings("no_bias", {{"msm.glsl", submitted("mutants/msm_no_moment_bias/msm.glsl")}}, "classic");
    EXPECT_NE(bias.find("the moment bias looks missing"), std::string::npos) << bias;
    EXPECT_EQ(bias.find("the guards look missing"), std::string::npos) << bias;
}

// A wrong power in computeMoments with z itself right is computeMoments's, not relativeDepth's;
// relativeDepth without its clamp is still told to clamp.
TEST(ReportHints, AWrongPowerWithTheRightDepthNamesComputeMoments) {
    std::string moments = test::readFile(test::root() / "reference/moments.glsl");
    const std::string b4 = "z2 * z2);";
    ASSERT_NE(moments.find(b4), std::string::npos) << "the reference's computeMoments changed";
    moments.replace(moments.find(b4), b4.size(), "z2 * z2 * z);");
    const std::string power = findings("b4_wrong", {{"moments.glsl", moments}}, "classic");
    EXPECT_NE(power.find("relativeDepth is right, look at computeMoments"), std::string::npos) << power;
    const std::string clamp = findings(
        "unclamped", {{"moments.glsl", submitted("mutants/moments_unclamped_relative_depth/moments.glsl")}},
        "classic");
    EXPECT_NE(clamp.find("relativeDepth must clamp"), std::string::npos) << clamp;
    EXPECT_EQ(clamp.find("look at computeMoments"), std::string::npos) << clamp;
}

// A wrong solve fails ordinary two- and three-point distributions too: that is the solve, not a
// missing guard or bias (the second blind student's swapped roots were told "the guards").
TEST(ReportHints, AWrongSolveIsTheSolveNotAGuardOrTheBias) {
    for (const char* mutant : {"msm_roots_swapped", "msm_forward_substitution_sign"}) {
        const std::string text = findings(
            mutant, {{"msm.glsl", submitted(std::string("mutants/") + mutant + "/msm.glsl")}}, "classic");
        EXPECT_NE(text.find("the solve itself looks off"), std::string::npos) << mutant << "\n" << text;
        EXPECT_EQ(text.find("the guards look missing"), std::string::npos) << mutant << "\n" << text;
        EXPECT_EQ(text.find("the moment bias looks missing"), std::string::npos) << mutant << "\n" << text;
    }
}

}  // namespace sl
