// The study: a tiny sweep (two techniques, two map sizes, 128² image) through the real
// pipeline: a CSV row per combination and no NaN, resumption, an error measure that can fail
// (a 128² map is worse than a 2048² one), and the page opened in headless Chromium.
#include "gl_test_support.h"
#include "study.h"
#include "study_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace sl {
namespace {

class Study : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        test::sharedContext();
        // CTest runs each test in its own process, maybe at once: one folder per process.
        dir_ = new fs::path(test::tempDir("study_tiny_" + std::to_string(::getpid())));
        StudyOptions o = tinyOptions();
        std::ostringstream log;
        summary_ = new StudySummary(runStudy(o, log));
    }
    static void TearDownTestSuite() {
        delete dir_;
        delete summary_;
    }
    static StudyOptions tinyOptions() {
        StudyOptions o;
        o.scene = test::scenePath("classic");
        o.techniques = {"msm4", "vsm"};
        o.mapSizes = {128, 2048};
        o.radii = {2};
        o.filters = {"gaussian"};
        o.repeats = 1;
        o.imageSize = 128;
        o.flickerFrames = 3;  // temporal stability (study_flicker.h)
        o.out = *dir_;
        o.progress = false;
        return o;
    }
    static fs::path* dir_;
    static StudySummary* summary_;
};
fs::path* Study::dir_ = nullptr;
StudySummary* Study::summary_ = nullptr;

TEST_F(Study, OneRowPerCombinationNoNaNWorseSmallMapAndReuse) {
    EXPECT_EQ(summary_->planned, 4);
    EXPECT_EQ(summary_->run, 4);
    const auto rows = readStudyCsv(*dir_ / "study.csv");
    ASSERT_EQ(rows.size(), 4u);
    std::set<std::string> keys;
    for (const StudyRow& r : rows) {
        keys.insert(r.key());
        for (double v : {r.frameMedian, r.frameRatio, r.copyMillis, r.truth.rmse, r.truth.max,
                         r.truth.p99, r.filtered.rmse, r.filtered.max})
            EXPECT_TRUE(std::isfinite(v)) << r.key();
        EXPECT_GT(r.frameRatio, 0.0) << r.key();
        // The cost: CPU time, its minimum no more than its median, the method named.
        EXPECT_LE(r.frameMin, r.frameMedian) << r.key();
        EXPECT_LE(r.frameMedian, r.frameMax) << r.key();
        EXPECT_NE(r.costMethod.find("CPU time"), std::string::npos) << r.costMethod;
        EXPECT_EQ(r.lightSize, 0.0) << "classic has a point light";
        EXPECT_GT(r.truth.pixels, 1000u) << r.key();
        EXPECT_GT(r.mapBytes, 0u);
        EXPECT_TRUE(fs::exists(*dir_ / r.errorMap)) << r.errorMap;
        EXPECT_TRUE(fs::exists(*dir_ / r.image)) << r.image;
    }
    EXPECT_EQ(keys.size(), 4u) << "duplicate combinations";
    // The raw text has no NaN anywhere either (a NaN would also fail to parse back as a number).
    std::ifstream in(*dir_ / "study.csv");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text.find("nan"), std::string::npos);
    // Map bytes follow the format: a map a filter stage reads is RGBA32F, 16 bytes a texel
    // (vsm's two channels fill half of it); vsm without a filter stores RG32F, 8.
    for (const StudyRow& r : rows)
        EXPECT_EQ(r.mapBytes, size_t(r.mapSize) * r.mapSize *
                                  (r.technique == "vsm" && r.filter == "none" ? 8u : 16u))
            << r.key();
    // (One test, not three: CTest runs each test in its own process, and each reruns the sweep.)
    // The error measure can fail: a 128² map is measurably worse than a 2048² one.
    for (const std::string tech : {"msm4", "vsm"}) {
        const StudyRow *small = nullptr, *large = nullptr;
        for (const StudyRow& r : rows)
            if (r.technique == tech) (r.mapSize == 128 ? small : large) = &r;
        ASSERT_TRUE(small && large) << tech;
        EXPECT_GT(small->truth.rmse, 1.3 * large->truth.rmse) << tech;
        EXPECT_GT(small->truth.p99, large->truth.p99) << tech;
        // ... and flickers more as the light turns: its edges jump by larger texels.
        EXPECT_GT(small->flicker, large->flicker) << tech;
    }
    // The light really moved: the truth changes (a cache keyed without the light's position
    // would give every frame the first frame's truth), the same for every row.
    for (const StudyRow& r : rows) {
        EXPECT_EQ(r.flickerFrames, 3) << r.key();
        EXPECT_GT(r.flickerTruth, 1e-5) << r.key();
        EXPECT_EQ(r.flickerTruth, rows[0].flickerTruth) << r.key();
    }
    // What was reused, said per row. Rows in order msm4 128, msm4 2048, vsm 128, vsm 2048: vsm
    // shares msm4's depth maps and filtered truths (same size, same kernel).
    EXPECT_NE(rows[0].reused.find("depth map 128² rendered"), std::string::npos) << rows[0].reused;
    EXPECT_NE(rows[2].reused.find("depth map 128² shared"), std::string::npos) << rows[2].reused;
    EXPECT_NE(rows[2].reused.find("filtered truth shared"), std::string::npos) << rows[2].reused;
}

TEST_F(Study, ResumesAndRedoesOnlyMissingRows) {
    const fs::path copy = test::tempDir("study_resume_" + std::to_string(::getpid()));
    fs::copy(*dir_ / "study.csv", copy / "study.csv");
    {   // Drop the last row and cut the one before short, as an interrupted sweep would.
        std::ifstream in(copy / "study.csv");
        std::vector<std::string> lines;
        for (std::string l; std::getline(in, l);) lines.push_back(l);
        ASSERT_EQ(lines.size(), 5u);
        std::ofstream out(copy / "study.csv", std::ios::trunc);
        for (size_t i = 0; i < 3; ++i) out << lines[i] << "\n";
        out << lines[3].substr(0, lines[3].size() / 2);  // no newline: cut mid-write
    }
    StudyOptions o = tinyOptions();
    o.out = copy;
    o.report = false;
    std::ostringstream log;
    const StudySummary s = runStudy(o, log);
    EXPECT_EQ(s.skipped, 2);
    EXPECT_EQ(s.run, 2);
    const auto rows = readStudyCsv(copy / "study.csv");
    EXPECT_EQ(rows.size(), 4u);
}

TEST_F(Study, PlotsAndPageOpenInHeadlessChromium) {
    for (const char* f : {"pareto.svg", "pareto.png", "pareto_bytes.svg", "pareto_bytes.png", "index.html"})
        EXPECT_TRUE(fs::exists(*dir_ / f)) << f;
    std::ifstream svg(*dir_ / "pareto.svg");
    std::string text((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("Pareto front"), std::string::npos);
    EXPECT_NE(text.find("msm4"), std::string::npos);
    EXPECT_NE(text.find("map 2048²"), std::string::npos) << "the legend names no map size";
    for (const char* f : {"kernel_cost.svg", "pass_cost.svg", "pass_cost.png", "pick.md"})
        EXPECT_TRUE(fs::exists(*dir_ / f)) << f;
    // Every crop the page shows exists (vsm leaks at 128² on classic: one at least).
    std::ifstream pageFile(*dir_ / "index.html");
    const std::string page((std::istreambuf_iterator<char>(pageFile)), std::istreambuf_iterator<char>());
    int crops = 0;
    for (size_t at = page.find("src=\"crops/"); at != std::string::npos;
         at = page.find("src=\"crops/", at + 1), ++crops)
        EXPECT_TRUE(fs::exists(*dir_ / page.substr(at + 5, page.find('"', at + 5) - at - 5)));
    EXPECT_GE(crops, 1);
    EXPECT_NE(page.find("Which configuration to pick"), std::string::npos);
    if (test::runCommand("command -v chromium").exitCode != 0)
        GTEST_SKIP() << "chromium is not installed (apt-get install chromium): page not opened";
    const fs::path shot = test::tempDir("study_shot") / "shot.png";
    const fs::path profile = test::tempDir("study_profile");
    auto r = test::screenshotPage(*dir_ / "index.html", shot, profile, 1200, 1600);
    ASSERT_TRUE(fs::exists(shot)) << r.output;
    EXPECT_GT(test::colourSpread(shot), 0.05) << "the screenshot is (nearly) one colour: a blank page";
}

}  // namespace
}  // namespace sl
