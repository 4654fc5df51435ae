// Hostile input (Gradescope matches tests by name): a test's name is the same for every submission
// (Gradescope matches tests by name): the robustness test is "hard cases: robustness" whether
// msm.glsl was graded or missing (it was "classic: robustness" then); and `--scenes a,a`
// grades a once.
#include "test_grader_support.h"

namespace sl {

TEST(HostileTestNames, RobustnessKeepsItsNameAndScenesAreGradedOnce) {
    auto sub = test::makeSubmission("names", {}, {"msm.glsl"});
    // The same scene twice, by name and by path.
    auto g = test::grade("--scenes classic,classic," + test::scenePath("classic").string() +
                             " --no-report --submission " + sub.string(),
                         test::tempDir("names_out"));
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    std::map<std::string, int> count;
    for (const auto& t : g.results["tests"]) ++count[t["name"].get<std::string>()];
    EXPECT_EQ(count["hard cases: robustness"], 1) << g.results.dump(1).substr(0, 2000);
    EXPECT_EQ(count["classic: robustness"], 0);
    EXPECT_EQ(count["classic: moments"], 1);
    EXPECT_NE(g.output("hard cases", "robustness").find("msm.glsl: not submitted"), std::string::npos);
}

}  // namespace sl
