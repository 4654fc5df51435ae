// Hostile input (one submission may not cost another its grade): in `grade --batch`, submissions
// were graded on threads of one process, so one submission that crashed the grader lost every
// student's grade. Each submission is graded by its own child process now: a crash costs that
// submission only, and it still gets a results.json and a row in scores.csv saying why.
#include "test_grader_support.h"

namespace sl {

TEST(HostileBatchIsolation, AGraderCrashOnOneSubmissionCostsOnlyThatOne) {
    const fs::path batch = test::tempDir("batch_isolation");
    const std::vector<std::string> drop = {"gaussian_blur.comp", "sat.comp", "sat_lookup.glsl", "msm.glsl"};
    fs::copy(test::makeSubmission("batch_a", {}, drop), batch / "alice");
    fs::copy(test::makeSubmission("batch_b", {}, drop), batch / "bob");
    const fs::path out = test::tempDir("batch_isolation_out");
    // The test hook makes the grading process itself crash (SIGSEGV) at bob's intake.
    const auto r = test::runCommand("SHADOWLAB_GRADER_FAULT=intake:bob " + test::shadowlabBinary() +
                                    " grade --batch " + batch.string() + " -j 2 --scenes classic "
                                    "--no-report --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto read = [&](const std::string& who) {
        std::ifstream in(out / who / "results.json");
        return nlohmann::json::parse(in, nullptr, false);
    };
    const auto alice = read("alice"), bob = read("bob");
    ASSERT_TRUE(alice.is_object() && bob.is_object());
    EXPECT_GT(alice["score"].get<double>(), 0.0);  // moments.glsl was graded
    EXPECT_EQ(bob["score"].get<double>(), 0.0);
    EXPECT_NE(bob["output"].get<std::string>().find("the grader crashed (SIGSEGV"), std::string::npos)
        << bob.dump(1);
    const std::string csv = test::readFile(out / "scores.csv");
    EXPECT_NE(csv.find("\nalice,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\nbob,0.00,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("the grader crashed"), std::string::npos) << csv;
}

}  // namespace sl
