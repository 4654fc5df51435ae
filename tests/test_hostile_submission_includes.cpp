// Hostile input (a correct submission must get its points): a submission's own include files.
// docs/stage_contract.md lets a stage file #include "other.glsl" next to it; the grader used to
// drop every non-stage file, so a correct SAT pair sharing a header lost the sat stage and every
// final test. Helpers are taken (bounded in count and size, no links, bare names only) and resolved
// inside the submission folder and shaders/ only.
#include "test_grader_support.h"

namespace sl {

TEST(HostileSubmissionIncludes, ACorrectSatPairSharingAHeaderScoresFull) {
    const fs::path alt = test::root() / "tests" / "submissions" / "alternatives" / "sat_shared_header";
    auto sub = test::makeSubmission("shared_header");
    for (const char* f : {"sat.comp", "sat_lookup.glsl", "sat_tile.glsl"})
        fs::copy_file(alt / f, sub / f, fs::copy_options::overwrite_existing);
    // A helper that is a link out of the folder is not taken (and the pair does not need it).
    fs::create_symlink(test::root() / "reference" / "msm.glsl", sub / "linked.glsl");
    auto g = test::grade("--scenes contact --no-report --submission " + sub.string(),
                         test::tempDir("hostile_includes_out"));
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    for (const char* stage : {"sat", "final", "moments", "msm"})
        EXPECT_TRUE(g.full("contact", stage)) << stage << ": " << g.output("contact", stage);
    const std::string out = g.results.value("output", std::string());
    EXPECT_EQ(out.find("sat_tile.glsl"), std::string::npos) << "taken, not ignored:\n" << out;
    EXPECT_NE(out.find("linked.glsl (refused: it is a symbolic link"), std::string::npos) << out;
}

TEST(HostileSubmissionIncludes, HelpersAreBoundedAndCannotReachOutside) {
    // Ten helpers: h01 includes a path and is refused; h02..h09 are taken (8, the limit);
    // h10 is not.
    auto sub = test::makeSubmission("many_helpers");
    for (int i = 2; i <= 10; ++i)
        std::ofstream(sub / ((i < 10 ? "h0" : "h") + std::to_string(i) + ".glsl")) << "// helper\n";
    std::ofstream(sub / "h01.glsl") << "#include \"../../reference/msm.glsl\"\n";
    // msm.glsl includes h10: not taken, so it is not found (a compile error).
    std::ofstream(sub / "msm.glsl", std::ios::app) << "#include \"h10.glsl\"\n";
    auto g = test::grade("--scenes classic --no-report --submission " + sub.string(),
                         test::tempDir("hostile_helpers_out"));
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    const std::string out = g.results.value("output", std::string());
    EXPECT_NE(out.find("h01.glsl (refused: line 1: #include \"../../reference/msm.glsl\" is a path"),
              std::string::npos) << out;
    EXPECT_NE(out.find("h10.glsl (more than 8 .glsl helpers)"), std::string::npos) << out;
    EXPECT_EQ(g.score("classic", "msm"), 0.0);
    EXPECT_NE(g.output("classic", "msm").find("h10.glsl: not found"), std::string::npos)
        << g.output("classic", "msm");
    EXPECT_TRUE(g.full("classic", "moments"));
}

}  // namespace sl
