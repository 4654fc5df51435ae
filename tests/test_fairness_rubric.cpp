// The rubric is validated like a scene (issue 7 §6): an unknown key, a stage typed "gausian",
// a visibility Gradescope does not know or a ramp upside down is an error naming the file, the
// JSON path and what was expected, written to results.json, before anything renders.
#include "test_grader_support.h"

namespace sl {
namespace {

// Grades the reference with `rubric` (the file's text); the rubric is read first, so an invalid
// one fails in well under a second.
test::Graded gradeWithRubric(const std::string& name, const std::string& rubric) {
    const fs::path dir = test::tempDir("fairness_rubric_" + name);
    std::ofstream(dir / "rubric.json") << rubric;
    return test::grade("--no-report --scenes classic --rubric " + (dir / "rubric.json").string() +
                           " --submission " + (test::root() / "reference").string(),
                       dir / "out");
}

struct BadRubric {
    const char* name;
    const char* json;
    const char* path;      // the JSON path the message must name
    const char* expected;  // and what it says was expected
};

TEST(FairnessRubric, InvalidRubricsAreRefusedWithTheJsonPath) {
    const BadRubric cases[] = {
        {"stage_typo", R"({"stages": {"gausian": {"weight": 30}}})", "/stages/gausian",
         "unknown key (known: final, gaussian, moments, msm, robustness, sat)"},
        {"visibility", R"({"hidden_scene_visibility": "after_due"})", "/hidden_scene_visibility",
         "expected one of \"visible\", \"hidden\", \"after_due_date\", \"after_published\", got \"after_due\""},
        {"top_key", R"({"totl": 100})", "/totl", "unknown key"},
        {"filters", R"({"filters": "one"})", "/filters", "expected one of \"both\", \"either\""},
        {"weight_type", R"({"stages": {"msm": {"weight": "20"}}})", "/stages/msm/weight",
         "expected a number, got \"20\""},
        {"negative_weight", R"({"stages": {"msm": {"weight": -1}}})", "/stages/msm/weight",
         "expected a number in [0, 1e+06]"},
        {"stage_key", R"({"stages": {"msm": {"wieght": 20}}})", "/stages/msm/wieght", "unknown key"},
        {"ramp", R"({"stages": {"sat": {"pass_fraction": 0.9, "zero_fraction": 0.95}}})",
         "/stages/sat/zero_fraction", "must be below pass_fraction"},
        {"tolerance_key", R"({"tolerances": {"moment_abs": 1e-4}})", "/tolerances/moment_abs",
         "unknown key"},
        {"tolerance_range", R"({"tolerances": {"shadow": 0}})", "/tolerances/shadow",
         "expected a number in (0, 1]"},
        {"not_object", R"([1, 2])", "/", "expected an object"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        auto g = gradeWithRubric(c.name, c.json);
        EXPECT_EQ(g.run.exitCode, 1) << g.run.output;
        ASSERT_TRUE(g.results.is_object()) << g.run.output;
        EXPECT_EQ(g.results["score"], 0);
        const std::string out = g.results["output"].get<std::string>();
        EXPECT_NE(out.find("rubric.json: " + std::string(c.path) + ": "), std::string::npos) << out;
        EXPECT_NE(out.find(c.expected), std::string::npos) << out;
    }
}

TEST(FairnessRubric, CommentsAreAcceptedAndRescaledPointsArePrinted) {
    // "_comment" keys are allowed in every object. classic has no SAT: the sat stage's 20
    // points are rescaled away, and the grade says what each stage is then worth (exact
    // hundredths, adding up to the total): 15, 20, 20, 5, 20 of 80 -> 18.75, 25, 25, 6.25, 25.
    auto g = gradeWithRubric("comment", R"({"_comment": "x", "stages": {"_note": 1, "msm": {"_why": "", "weight": 20}}})");
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    EXPECT_DOUBLE_EQ(g.results["score"].get<double>(), 100.0) << g.run.output;
    const std::string line = "points per stage (weights rescaled to the total 100.00): moments "
                             "18.75, gaussian 25.00, msm 25.00, robustness 6.25, final 25.00";
    EXPECT_NE(g.run.output.find(line), std::string::npos) << g.run.output;
    EXPECT_NE(g.results["output"].get<std::string>().find(line), std::string::npos);
    EXPECT_NE(g.run.output.find("filters: both"), std::string::npos) << g.run.output;
}

}  // namespace
}  // namespace sl
