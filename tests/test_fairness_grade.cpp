// Fair grades (a grade must be fair and explainable): the "either" filter mode with one-filter
// submissions, points that add up exactly (displayed points, status and totals agree), the
// worst-texel rule naming the texel, and a stubbed relativeDepth reported as not implemented.
#include "test_grader_support.h"

#include <cmath>

namespace sl {
namespace {

// The reference with the given stage files taken from student/ (the stubs).
fs::path withStubs(const std::string& name, const std::vector<std::string>& stubs) {
    std::map<std::string, std::string> replace;
    for (const auto& f : stubs) replace[f] = test::readFile(test::root() / "student" / f);
    return test::makeSubmission(name, replace);
}

fs::path eitherRubric() {
    const fs::path dir = test::tempDir("fairness_either_rubric");
    std::ofstream(dir / "rubric.json") << R"({"filters": "either"})";
    return dir / "rubric.json";
}

long hundredths(const nlohmann::json& v) { return std::lround(v.get<double>() * 100.0); }

// Every test: status "passed" exactly when score == max_score; the maxima add up to the total
// and the scores to the score, in exact hundredths.
void expectPointsAgree(const test::Graded& g, long totalHundredths = 10000) {
    long max = 0, score = 0;
    for (const auto& t : g.results["tests"]) {
        SCOPED_TRACE(t["name"].get<std::string>());
        const long s = hundredths(t["score"]), m = hundredths(t["max_score"]);
        EXPECT_NEAR(t["score"].get<double>() * 100.0, double(s), 1e-6) << "not in hundredths";
        EXPECT_EQ(t["status"] == "passed", s == m) << t["output"];
        EXPECT_LE(s, m);
        max += m;
        score += s;
    }
    EXPECT_EQ(max, totalHundredths);
    EXPECT_EQ(score, hundredths(g.results["score"]));
}

std::map<std::string, std::pair<long, long>> byStage(const test::Graded& g) {
    std::map<std::string, std::pair<long, long>> stages;
    for (const auto& t : g.results["tests"]) {
        const std::string stage = t["tags"][0].get<std::string>().substr(6);
        stages[stage].first += hundredths(t["score"]);
        stages[stage].second += hundredths(t["max_score"]);
    }
    return stages;
}

TEST(FairnessGrade, EitherFilterGivesTheFilterPointsToTheImplementedOne) {
    // A SAT-only submission (the Gaussian is the stub), on two Gaussian scenes and one SAT
    // scene: three scenes split msm's 20 points into 6.67 + 6.67 + 6.66.
    const fs::path satOnly = withStubs("sat_only", {"gaussian_blur.comp"});
    const std::string scenes = " --no-report --scenes classic,grazing,contact --submission ";
    auto both = test::grade(scenes + satOnly.string(), test::tempDir("fairness_sat_only_both"));
    ASSERT_EQ(both.run.exitCode, 0) << both.run.output;
    EXPECT_NE(both.run.output.find("filters: both"), std::string::npos) << both.run.output;
    EXPECT_EQ(both.score("classic", "gaussian"), 0.0);
    EXPECT_LT(both.results["score"].get<double>(), 80.0);
    expectPointsAgree(both);
    EXPECT_EQ(both.maxScore("classic", "msm") + both.maxScore("grazing", "msm") +
                  both.maxScore("contact", "msm"), 20.0);
    EXPECT_EQ(both.maxScore("classic", "msm"), 6.67);
    EXPECT_EQ(both.maxScore("grazing", "msm"), 6.66);  // tests in scene order: classic, contact, grazing

    auto either = test::grade("--rubric " + eitherRubric().string() + scenes + satOnly.string(),
                              test::tempDir("fairness_sat_only_either"));
    ASSERT_EQ(either.run.exitCode, 0) << either.run.output;
    EXPECT_EQ(hundredths(either.results["score"]), 10000) << either.run.output;
    EXPECT_NE(either.run.output.find("filters: either (rubric): the filter points go to sat"),
              std::string::npos) << either.run.output;
    EXPECT_NE(either.results["output"].get<std::string>().find("filters: either"), std::string::npos);
    const auto stages = byStage(either);
    EXPECT_FALSE(stages.count("gaussian"));
    EXPECT_EQ(stages.at("sat").second, 4000);  // gaussian's 20 + sat's 20
    EXPECT_EQ(either.score("classic", "final"), -1.0) << "final needs the filter not implemented";
    EXPECT_TRUE(either.full("contact", "final"));
    expectPointsAgree(either);

    // A Gaussian-only submission: the points go the other way.
    const fs::path gaussianOnly = withStubs("gaussian_only", {"sat.comp", "sat_lookup.glsl"});
    auto g = test::grade("--rubric " + eitherRubric().string() +
                             " --no-report --scenes classic,contact --submission " + gaussianOnly.string(),
                         test::tempDir("fairness_gaussian_only_either"));
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    EXPECT_EQ(hundredths(g.results["score"]), 10000) << g.run.output;
    EXPECT_NE(g.run.output.find("the filter points go to gaussian"), std::string::npos) << g.run.output;
    EXPECT_FALSE(byStage(g).count("sat"));
    expectPointsAgree(g);
}

TEST(FairnessGrade, StubbedRelativeDepthIsNotImplementedAndBorderBugsNameTheirTexel) {
    // relativeDepth is the stub, computeMoments is right: the shadow map holds (-1, 1, -1, 1),
    // which is no stub value; the depth ladder tells.
    std::string moments = test::readFile(test::root() / "reference" / "moments.glsl");
    const std::string clamp = "return clamp((lightDepth - depthRange.x) / (depthRange.y - depthRange.x), 0.0, 1.0);";
    ASSERT_NE(moments.find(clamp), std::string::npos);
    moments.replace(moments.find(clamp), clamp.size(), "return -1.0;");
    const fs::path stub = test::makeSubmission("relative_depth_stub", {{"moments.glsl", moments}});
    // The mirror mutant of the catalogue: only the map's border is off.
    const fs::path mirror = test::makeSubmission(
        "gaussian_mirror",
        {{"gaussian_blur.comp", test::readFile(test::root() / "tests" / "submissions" / "mutants" /
                                               "gaussian_edge_mirror" / "gaussian_blur.comp")}});
    // Both in one --batch: the reference renders once for the two.
    auto graded = test::gradeBatch({{"relative_depth_stub", stub}, {"gaussian_mirror", mirror}},
                                   "--no-report --scenes classic",
                                   test::tempDir("fairness_stub_and_mirror"));
    const test::Graded& a = graded["relative_depth_stub"];
    ASSERT_EQ(a.run.exitCode, 0) << a.run.output;
    EXPECT_EQ(a.score("classic", "moments"), 0.0);
    EXPECT_NE(a.output("classic", "moments").find("not implemented: submission/moments.glsl: relativeDepth"),
              std::string::npos) << a.output("classic", "moments");
    expectPointsAgree(a);

    const test::Graded& b = graded["gaussian_mirror"];
    ASSERT_EQ(b.run.exitCode, 0) << b.run.output;
    const std::string out = b.output("classic", "gaussian");
    // Fewer than 0.5 % of the texels are off, but by far more than 5x the tolerance.
    EXPECT_LE(b.score("classic", "gaussian"), 0.5 * b.maxScore("classic", "gaussian")) << out;
    EXPECT_NE(out.find("worst-texel rule"), std::string::npos) << out;
    EXPECT_NE(out.find("worst texel: x "), std::string::npos) << out;
    EXPECT_TRUE(b.full("classic", "moments"));
    EXPECT_TRUE(b.full("classic", "msm"));
    // The table prints the whole reason, which says where: mirrored taps differ at the border.
    EXPECT_NE(b.run.output.find("worst-texel rule: a texel at the map's border (look at the border rule) is off "
                                "by more than 5x the tolerance, at most 50% of the points"),
              std::string::npos) << b.run.output;
    expectPointsAgree(b);
}

}  // namespace
}  // namespace sl
