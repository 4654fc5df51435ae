// The report for a regrade (what an instructor needs to regrade): a per-stage summary at the top;
// known failure patterns in words (a red frame on the border, the moment bias, failures only on SAT
// scenes, NaN); metrics as tables, not JSON dumps; previews that link full-size images; hidden
// scenes left out of report/ (images included) and marked in the staff page. The synthetic
// summaries below are unit tests of the page; the last test grades two real mutants.
#include "test_grader_support.h"

#include "image_io.h"
#include "report.h"

#include <regex>

namespace sl {
namespace {

using grader::Comparison;
using grader::GradeSummary;
using grader::ReportWriter;
using grader::TestResult;

TestResult result(const std::string& scene, const std::string& stage, double score, double max,
                bool hidden = false) {
    TestResult t;
    t.scene = scene, t.stage = stage, t.score = score, t.maxScore = max, t.hidden = hidden;
    t.output = score < max ? "97.00% within tolerance\ndetail line\n" : "full marks\n";
    t.images = {stage == "final" ? "final" : stage == "msm" ? "shadow" : "moments_filtered"};  // compared
    return t;
}

// A comparison whose error map fails (value 5: 5x the tolerance) on `bad` texels.
Comparison comparison(int size, const std::function<bool(int, int)>& bad, long nonFinite = 0) {
    Comparison c;
    c.errorMap = Image(size, size, 1, 0.1f);
    long failing = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            if (bad(x, y)) c.errorMap.at(x, y, 0) = 5.0f, ++failing;
    c.fraction = 1.0 - double(failing) / (double(size) * size);
    c.nonFinite = nonFinite;
    c.mean = 0.001, c.rms = 0.002, c.max = 0.5, c.psnr = 41.5;
    return c;
}

std::vector<std::string> links(const std::string& page) {
    std::vector<std::string> out;
    const std::regex href("href=\"([^\"#][^\"]*)\"");
    for (auto it = std::sregex_iterator(page.begin(), page.end(), href); it != std::sregex_iterator(); ++it)
        out.push_back((*it)[1].str());
    return out;
}

}  // namespace

TEST(InstructorReport, SummaryPatternsTablesFullSizeImagesAndNoHiddenScene) {
    const fs::path out = test::tempDir("instructor_report_unit");
    ReportWriter report(out / "report");
    GradeSummary s;
    s.referenceMode = "golden";
    TestResult gauss = result("classic", "gaussian", 18.5, 20);
    TestResult moments = result("classic", "moments", 15, 15);
    TestResult hard = result("hard cases", "robustness", 3, 5);
    TestResult secret = result("secret_shelf", "moments", 0, 15, true);
    // A mirrored border: wrong texels in the outer 3 columns/rows of a 1024 map only.
    const Image map(1024, 1024, 4, 0.5f);
    report.add(gauss, "moments_filtered", map, map,
               comparison(1024, [](int x, int y) { return x < 3 || y > 1020; }));
    report.add(moments, "moments_raw", map, map, comparison(1024, [](int, int) { return false; }));
    report.add(secret, "moments_raw", map, map, comparison(1024, [](int x, int) { return x > 500; }));
    hard.metrics["robustness"] = {
        {"cases", 289}, {"failed", 5},
        {"failing", {{{"case", "constant-depth/z0.3/zf0.25"}, {"b", {0.3, 0.09, 0.027, 0.0081}}, {"zf", 0.25}, {"G", 0.4}, {"problems", "off from the exact value"}},
                     {{"case", "constant-depth/z0.3/zf0.299"}, {"b", {0.3, 0.09, 0.027, 0.0081}}, {"zf", 0.299}, {"G", 0.5}, {"problems", "off from the exact value"}},
                     {{"case", "constant-depth/z0.5/zf0.45"}, {"b", {0.5, 0.25, 0.125, 0.0625}}, {"zf", 0.45}, {"G", 0.5}, {"problems", "off from the exact value"}},
                     {{"case", "constant-depth/z0.9/zf0.85"}, {"b", {0.9, 0.81, 0.729, 0.6561}}, {"zf", 0.85}, {"G", 0.6}, {"problems", "off from the exact value"}},
                     {{"case", "discriminant/d0/zf0.5"}, {"b", {0.5, 0.3, 0.2, 0.15}}, {"zf", 0.5}, {"G", "nan"}, {"problems", "NaN"}}}}};
    s.tests = {gauss, moments, hard, secret};
    for (const auto& t : s.tests) s.score += t.score, s.maxScore += t.maxScore;
    report.finish(s);

    const std::string page = test::readFile(out / "report" / "index.html");
    // The summary comes first, one row per stage, with the points of visible tests only.
    const size_t summary = page.find("<h2>Summary</h2>");
    ASSERT_NE(summary, std::string::npos);
    EXPECT_LT(summary, page.find("<h2>Tests</h2>"));
    EXPECT_NE(page.find("<td>gaussian</td><td>18.50 / 20.00</td><td>0 of 1</td><td>classic</td>"), std::string::npos);
    EXPECT_NE(page.find("<td>moments</td><td>15.00 / 15.00</td><td>1 of 1</td><td>full marks</td>"), std::string::npos);
    EXPECT_NE(page.find("Shadowlab grade: 36.50 / 40.00"), std::string::npos);  // not / 55
    // Patterns in words.
    EXPECT_NE(page.find("lie within 3 texels of the border"), std::string::npos) << page;
    EXPECT_NE(page.find("check the border rule"), std::string::npos);
    EXPECT_NE(page.find("the moment bias looks missing"), std::string::npos);
    EXPECT_NE(page.find("1 hard cases give NaN or Inf"), std::string::npos);
    // Tables, not JSON dumps.
    EXPECT_EQ(page.find("fraction_within_tolerance"), std::string::npos);
    EXPECT_EQ(page.find("{\""), std::string::npos);
    EXPECT_NE(page.find("<td>constant-depth/z0.5/zf0.45</td>"), std::string::npos);
    EXPECT_NE(page.find("<td>99.41%</td>"), std::string::npos);  // 1 − (6·1024 − 9) / 1024²
    // Hidden: not named, no images; the page says hidden tests exist.
    EXPECT_EQ(page.find("secret_shelf"), std::string::npos);
    EXPECT_NE(page.find("1 tests on hidden scenes"), std::string::npos);
    for (const auto& f : fs::recursive_directory_iterator(out / "report"))
        EXPECT_EQ(f.path().string().find("secret_shelf"), std::string::npos) << f.path();
    // Every link resolves; the failing 1024² image links its full-size heat-map.
    bool fullDiff = false;
    for (const auto& l : links(page)) {
        EXPECT_TRUE(fs::exists(out / "report" / l)) << l;
        fullDiff = fullDiff || l == "img/classic_gaussian_moments_filtered_diff_full.png";
    }
    EXPECT_TRUE(fullDiff);
    int w = 0, h = 0;
    {
        auto full = readImage(out / "report" / "img" / "classic_gaussian_moments_filtered_diff_full.png");
        w = full.width, h = full.height;
    }
    EXPECT_EQ(w, 1024);
    EXPECT_EQ(h, 1024);

    // The staff page: the hidden scene, marked, its images in report-staff/; links resolve.
    const std::string staff = test::readFile(out / "report-staff" / "index.html");
    EXPECT_NE(staff.find("secret_shelf</a> <span class=\"hidden-badge\">hidden</span>"), std::string::npos);
    EXPECT_NE(staff.find("Shadowlab grade: 36.50 / 55.00"), std::string::npos);
    for (const auto& l : links(staff)) EXPECT_TRUE(fs::exists(out / "report-staff" / l)) << l;
    EXPECT_TRUE(fs::exists(out / "report-staff" / "img" / "secret_shelf_moments_moments_raw_diff.png"));
}

TEST(InstructorReport, FailuresOnlyOnSatScenesAndNaNAreNamed) {
    const fs::path out = test::tempDir("instructor_report_sat");
    ReportWriter report(out / "report");
    GradeSummary s;
    s.referenceMode = "live";
    const Image img(64, 64, 3, 0.2f);
    s.tests = {result("classic", "gaussian", 20, 20), result("classic", "final", 10, 10),
               result("contact", "sat", 12, 20), result("contact", "final", 7, 10),
               result("wide_blur", "sat", 15, 20)};
    report.add(s.tests[3], "final", img, img, comparison(64, [](int x, int y) { return x == 30 && y < 9; }, 9));
    report.finish(s);
    const std::string page = test::readFile(out / "report" / "index.html");
    EXPECT_NE(page.find("only on the SAT scenes (contact, wide_blur)"), std::string::npos) << page;
    EXPECT_NE(page.find("NaN or Inf values in the final stage's output (contact)"), std::string::npos);
    EXPECT_EQ(page.find("border rule"), std::string::npos);  // a column in the middle is no frame
    EXPECT_FALSE(fs::exists(out / "report-staff"));          // no hidden scene, no staff page
}

// A plain float table fails where its sums are largest, away from texel (0, 0) (the fragile
// naive_sat: 100 % of contact's 37 889 failing texels): the report says so. A wrong corner
// fails on both halves, a border rule in the frame: neither is called a float table's rounding.
TEST(InstructorReport, SatFailuresAwayFromTheTablesOriginAreCalledItsPrecision) {
    const Image img(64, 64, 3, 0.2f);
    auto page = [&](const std::string& name, const std::function<bool(int, int)>& bad) {
        const fs::path out = test::tempDir("instructor_report_far_" + name);
        ReportWriter report(out / "report");
        GradeSummary s;
        s.referenceMode = "live";
        s.tests = {result("contact", "sat", 5, 20)};
        report.add(s.tests[0], "moments_filtered", img, img, comparison(64, bad));
        report.finish(s);
        return test::readFile(out / "report" / "index.html");
    };
    const std::string far = "away from texel (0, 0)";
    const std::string rounding = page("rounding", [](int x, int y) { return x + y > 80 && x < 58 && y < 58 && (x + y) % 3 == 0; });
    EXPECT_NE(rounding.find("contact (sat, moments_filtered): 100% of the"), std::string::npos) << rounding;
    EXPECT_NE(rounding.find(far), std::string::npos) << rounding;
    EXPECT_EQ(rounding.find("border rule"), std::string::npos);
    const std::string everywhere = page("everywhere", [](int x, int y) { return (x + 2 * y) % 7 == 0; });
    EXPECT_EQ(everywhere.find(far), std::string::npos) << everywhere;
    const std::string frame = page("frame", [](int x, int y) { return x > 61 || y > 61; });
    EXPECT_NE(frame.find("border rule"), std::string::npos) << frame;
    EXPECT_EQ(frame.find(far), std::string::npos) << frame;
}

// Three real mutants (a Gaussian that mirrors at the border, an MSM without the moment bias, a
// relativeDepth that does not clamp): the report says each in words, and the score table too.
// The unclamped relativeDepth is the depth-ladder probe's (every moment map is right), not a
// border rule (the ladder is one row of light depths, all of it "near the border").
TEST(InstructorReport, ARealGradeNamesTheBorderTheMomentBiasAndTheDepthLadder) {
    const fs::path mutants = test::root() / "tests/submissions/mutants";
    const fs::path sub = test::makeSubmission(
        "instructor_report_mutants",
        {{"gaussian_blur.comp", test::readFile(mutants / "gaussian_edge_mirror/gaussian_blur.comp")},
         {"msm.glsl", test::readFile(mutants / "msm_no_moment_bias/msm.glsl")},
         {"moments.glsl", test::readFile(mutants / "moments_unclamped_relative_depth/moments.glsl")}});
    const fs::path out = test::tempDir("instructor_report_mutants_out");
    auto g = test::grade("--reference live --scenes classic --submission " + sub.string(), out);
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    const std::string page = test::readFile(out / "report" / "index.html");
    EXPECT_NE(page.find("classic (gaussian, moments_filtered)"), std::string::npos) << page;
    EXPECT_NE(page.find("check the border rule"), std::string::npos) << page;
    EXPECT_NE(page.find("the moment bias looks missing"), std::string::npos) << page;
    const std::string ladder = "the depth-ladder probe finds 36 of its 75 light depths off, all "
                               "outside [near, far]: relativeDepth must clamp";
    EXPECT_NE(page.find("classic (moments): " + ladder), std::string::npos) << page;
    EXPECT_EQ(page.find("moments_raw_depth_ladder): "), std::string::npos) << page;  // no frame
    EXPECT_EQ(g.output("classic", "moments").rfind(ladder, 0), 0u) << g.output("classic", "moments");
    EXPECT_NE(g.output("classic", "moments").find("every moment map within tolerance"), std::string::npos)
        << g.output("classic", "moments");
    EXPECT_NE(g.run.output.find("classic: " + ladder), std::string::npos) << g.run.output;
    EXPECT_NE(g.run.output.find("  - classic (moments): " + ladder), std::string::npos) << g.run.output;
    for (const auto& l : links(page)) EXPECT_TRUE(fs::exists(out / "report" / l)) << l;
}

}  // namespace sl
