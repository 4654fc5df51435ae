// Hidden scenes (hidden from students until the due date): a hidden scene's tests reach
// results.json with their own visibility, but nothing a student sees before the due date names the
// scene, shows its errors or counts its points: the score table on stdout, results.json's top-level
// output, the warnings, report/. `--help` for --scenes mentions the keyword "public".
#include "test_grader_support.h"

#include "results.h"
#include "scene_list.h"
#include "rubric.h"

namespace sl {
namespace {

using grader::GradeSummary;
using grader::TestResult;

TestResult result(const std::string& scene, const std::string& stage, double score, double max,
                const std::string& output, bool hidden = false) {
    TestResult t;
    t.scene = scene, t.stage = stage, t.score = score, t.maxScore = max, t.output = output;
    t.hidden = hidden;
    return t;
}

// Two public tests (15 of 20 points) and two on the hidden scene "secret_shelf" (3 of 20).
GradeSummary withHiddenScene() {
    GradeSummary s;
    s.referenceMode = "live";
    s.tests = {result("classic", "moments", 10, 10, "full marks\n"),
               result("classic", "msm", 5, 10, "96.00% within tolerance (full marks from 98.0%)\n"),
               result("secret_shelf", "moments", 0, 10,
                    "compile or link error:\nsubmission/moments.glsl:3: shelf-only detail\n", true),
               result("secret_shelf", "msm", 3, 10, "91.00% within tolerance\n", true)};
    s.score = 18, s.maxScore = 40;
    s.warnings = {"scene secret_shelf changed since its goldens were made",
                  "ignored (not stage files): notes.txt"};
    return s;
}

}  // namespace

TEST(InstructorHidden, ScoreTableNamesNoHiddenSceneAndCountsVisiblePointsOnly) {
    std::ostringstream out;
    grader::printScoreTable(out, withHiddenScene());
    const std::string table = out.str();
    EXPECT_EQ(table.find("secret_shelf"), std::string::npos) << table;
    EXPECT_EQ(table.find("shelf-only detail"), std::string::npos) << table;
    EXPECT_EQ(table.find("91.00%"), std::string::npos) << table;
    // Visible points only: moments 10 of 10, msm 5 of 10, total 15 of 20 (not 18 of 40).
    EXPECT_NE(table.find("10.00/10.00"), std::string::npos) << table;
    EXPECT_NE(table.find("5.00/10.00"), std::string::npos) << table;
    EXPECT_NE(table.find("15.00/20.00"), std::string::npos) << table;
    EXPECT_EQ(table.find("40.00"), std::string::npos) << table;
    EXPECT_NE(table.find("classic: 96.00%"), std::string::npos) << table;  // public losses stay
    EXPECT_NE(table.find("notes.txt"), std::string::npos) << table;        // public warnings stay
    EXPECT_NE(table.find("hidden"), std::string::npos) << table;           // says there are some
}

TEST(InstructorHidden, ResultsJsonKeepsHiddenTestsWithTheirVisibilityButNotInItsOutput) {
    const nlohmann::json r = grader::resultsJson(withHiddenScene(), grader::defaultRubric());
    const std::string output = r["output"].get<std::string>();
    EXPECT_EQ(output.find("secret_shelf"), std::string::npos) << output;
    EXPECT_NE(output.find("15.00 / 20.00"), std::string::npos) << output;
    EXPECT_DOUBLE_EQ(r["score"].get<double>(), 18.0);  // Gradescope's total: every test
    int hidden = 0;
    for (const auto& t : r["tests"]) {
        if (t["name"].get<std::string>().rfind("secret_shelf", 0) != 0) {
            EXPECT_EQ(t["visibility"], "visible") << t;
            EXPECT_EQ(t["output"].get<std::string>().find("secret_shelf"), std::string::npos) << t;
            continue;
        }
        ++hidden;
        EXPECT_EQ(t["visibility"], "after_due_date") << t;
        // The staff-only warning about the scene travels with its (after-due-date) tests.
        EXPECT_NE(t["output"].get<std::string>().find("changed since its goldens"), std::string::npos) << t;
    }
    EXPECT_EQ(hidden, 2);
}

TEST(InstructorHidden, HelpForScenesMentionsThePublicKeyword) {
    for (const char* command : {"grade", "golden"}) {
        auto r = test::runCommand(test::shadowlabBinary() + " " + command + " --help");
        ASSERT_EQ(r.exitCode, 0) << r.output;
        const size_t at = r.output.find("--scenes");
        ASSERT_NE(at, std::string::npos) << r.output;
        EXPECT_NE(r.output.find("\"public\"", at), std::string::npos) << command << ":\n" << r.output;
        EXPECT_NE(r.output.find("hidden", at), std::string::npos) << command << ":\n" << r.output;
    }
}

// End to end: the stubs graded on classic and a hidden copy of contact. The hidden tests are in
// results.json (after_due_date); stdout, the top-level output and report/ never name them.
TEST(InstructorHidden, AGradeWithAHiddenSceneShowsStudentsNothingOfIt) {
    const fs::path dir = test::tempDir("instructor_hidden_grade");
    fs::create_directories(dir / "private");
    const fs::path scene = dir / "private" / "secret_shelf.json";
    fs::copy_file(test::scenePath("contact"), scene);
    const fs::path out = dir / "out";
    // The hidden scene first: its renders are then the stub stages' scouts (grade.cpp), and the
    // public scenes' tests they stand in for must not name it.
    auto g = test::grade("--reference live --scenes " + scene.string() + ",classic" +
                             " --submission " + (test::root() / "student").string(), out);
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    EXPECT_EQ(g.run.output.find("secret_shelf"), std::string::npos) << g.run.output;
    EXPECT_NE(g.run.output.find("classic: not implemented"), std::string::npos) << g.run.output;

    // results.json: every test, hidden ones after the due date; visible maxima in the output.
    double visibleMax = 0;
    int hidden = 0;
    for (const auto& t : g.results["tests"]) {
        const bool isHidden = t["name"].get<std::string>().rfind("secret_shelf", 0) == 0;
        EXPECT_EQ(t["visibility"], isHidden ? "after_due_date" : "visible") << t;
        hidden += isHidden;
        if (!isHidden) EXPECT_EQ(t["output"].get<std::string>().find("secret_shelf"), std::string::npos) << t;
        if (!isHidden) visibleMax += t["max_score"].get<double>();
    }
    EXPECT_EQ(hidden, 4);  // moments, sat, msm, final
    const std::string output = g.results["output"].get<std::string>();
    EXPECT_EQ(output.find("secret_shelf"), std::string::npos) << output;
    char total[64];
    std::snprintf(total, sizeof total, "0.00 / %.2f", visibleMax);
    EXPECT_NE(output.find(total), std::string::npos) << output << " expected " << total;
    EXPECT_NE(g.run.output.find(std::string(total).replace(4, 3, "/")), std::string::npos)
        << g.run.output;  // the table's total: "0.00/<visible max>"

    // report/ (may be forwarded): no hidden name, no hidden image; report-staff/ has them, marked.
    const std::string page = test::readFile(out / "report" / "index.html");
    EXPECT_EQ(page.find("secret_shelf"), std::string::npos);
    for (const auto& f : fs::recursive_directory_iterator(out / "report"))
        EXPECT_EQ(f.path().filename().string().find("secret_shelf"), std::string::npos) << f.path();
    const std::string staff = test::readFile(out / "report-staff" / "index.html");
    EXPECT_NE(staff.find("secret_shelf"), std::string::npos);
    EXPECT_NE(staff.find("hidden-badge"), std::string::npos);
    // (Its SAT render: the scene's other stub stages are not rendered, grade.cpp's scouts.)
    EXPECT_TRUE(fs::exists(out / "report-staff" / "img" / "secret_shelf_sat_moments_filtered_ref.png"));
}

}  // namespace sl

namespace sl {

TEST(InstructorHidden, HiddenMeansWhatStudentsDoNotHave) {
    const fs::path scenes = test::root() / "scenes";
    EXPECT_FALSE(grader::isHiddenScenePath(scenes / "classic.json"));
    EXPECT_FALSE(grader::isHiddenScenePath(scenes / "ladder" / "x.json"));  // ships to students
    EXPECT_TRUE(grader::isHiddenScenePath(scenes / "hidden" / "shelf.json"));
    EXPECT_TRUE(grader::isHiddenScenePath(scenes / ".." / "private" / "shelf.json"));
    EXPECT_TRUE(grader::isHiddenScenePath("/course/private/shelf.json"));
}

TEST(InstructorHidden, SceneListGradesEachSceneOnceAndRefusesTwoScenesOfOneName) {
    const auto all = grader::gradedScenes();
    const auto twice = grader::gradedScenes({"classic", "public", test::scenePath("classic").string()});
    ASSERT_EQ(twice.size(), all.size());
    for (size_t i = 0; i < all.size(); ++i) EXPECT_EQ(twice[i].name, all[i].name);  // classic first
    const fs::path dir = test::tempDir("instructor_scene_names");
    fs::copy_file(test::scenePath("contact"), dir / "classic.json");
    try {
        grader::gradedScenes({"classic", (dir / "classic.json").string()});
        ADD_FAILURE() << "two scenes named classic were accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("two scenes are named \"classic\""), std::string::npos) << e.what();
    }
}

}  // namespace sl
