// The study split and joined: shards of one sweep, merged, give the table one process writes
// (the same rows in the same order, the same images bit for bit, the same errors and map
// sharing; only the measured costs and the `reused` wording may differ), and the light-size
// axis: each size scored against its own truth (hard for 0, the area integral otherwise).
#include "gl_test_support.h"
#include "study.h"
#include "study_shard.h"
#include "study_table.h"

#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <unistd.h>

namespace sl {
namespace {

StudyOptions smallSweep(const fs::path& out) {
    StudyOptions o;
    o.scene = test::scenePath("classic");
    o.techniques = {"hard", "msm4"};
    o.mapSizes = {128, 256};
    o.radii = {1, 2};
    o.filters = {"gaussian"};
    o.lightSizes = {0.0, 0.6};
    o.repeats = 1;
    o.imageSize = 96;
    o.samples = 16;  // the area truth's noise does not matter here, its being traced does
    o.out = out;
    o.progress = false;
    o.report = false;
    return o;
}

class StudyShards : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        test::sharedContext();
        base_ = new fs::path(test::tempDir("study_shard_" + std::to_string(::getpid())));
        std::ostringstream log;
        runStudy(smallSweep(*base_ / "one"), log);
    }
    static void TearDownTestSuite() { delete base_; }
    static fs::path* base_;
};
fs::path* StudyShards::base_ = nullptr;

TEST_F(StudyShards, ShardsMergeToTheOneProcessTable) {
    const auto one = readStudyCsv(*base_ / "one" / "study.csv");
    ASSERT_EQ(one.size(), 12u);  // 2 light sizes × (hard 2 sizes + msm4 2 sizes × 2 radii)
    std::vector<fs::path> shards;
    int planned = 0;
    for (int k = 1; k <= 3; ++k) {
        StudyOptions o = smallSweep(*base_ / ("shard" + std::to_string(k)));
        o.shard = k, o.shards = 3;
        std::ostringstream log;
        const StudySummary s = runStudy(o, log);
        EXPECT_GT(s.run, 0) << "shard " << k << " of 3 got no rows";
        planned += s.planned;
        shards.push_back(o.out);
    }
    EXPECT_EQ(planned, 12) << "the shards do not split the sweep";
    StudyOptions merge = smallSweep(*base_ / "merged");
    merge.mergeFrom = shards;
    std::ostringstream log;
    const StudySummary m = runStudy(merge, log);
    EXPECT_EQ(m.run, 0) << "the merge left rows to run";
    const auto merged = readStudyCsv(*base_ / "merged" / "study.csv");
    ASSERT_EQ(merged.size(), one.size());
    for (size_t i = 0; i < one.size(); ++i) {
        const StudyRow &a = one[i], &b = merged[i];
        ASSERT_EQ(a.key(), b.key()) << "row " << i << ": not in the one process's order";
        EXPECT_EQ(a.imageDigest, b.imageDigest) << a.key();
        EXPECT_EQ(a.truth.rmse, b.truth.rmse) << a.key();
        EXPECT_EQ(a.filtered.rmse, b.filtered.rmse) << a.key();
        EXPECT_EQ(a.truth.leakArea, b.truth.leakArea) << a.key();
        EXPECT_EQ(a.mapKey, b.mapKey) << a.key();
        EXPECT_EQ(a.mapFrom, b.mapFrom) << a.key() << ": a shard split a group sharing a map";
        EXPECT_EQ(a.parameters, b.parameters) << a.key();
        EXPECT_TRUE(fs::exists(*base_ / "merged" / b.image)) << b.image;
    }
    int bad = 0, k = 0, n = 0;
    for (const char* text : {"0/3", "4/3", "2", "1/x", "1/0"}) {
        try {
            parseShard(text, k, n);
        } catch (const std::invalid_argument&) {
            ++bad;
        }
    }
    EXPECT_EQ(bad, 5);
}

TEST_F(StudyShards, EachLightSizeIsScoredAgainstItsOwnTruth) {
    const auto rows = readStudyCsv(*base_ / "one" / "study.csv");
    std::map<std::string, std::map<double, const StudyRow*>> bySetting;
    for (const StudyRow& r : rows)
        bySetting[r.spec + "|" + r.filter + "|" + std::to_string(r.radius) + "|" +
                  std::to_string(r.mapSize)][r.lightSize] = &r;
    ASSERT_EQ(bySetting.size(), 6u);
    for (const auto& [setting, sizes] : bySetting) {
        ASSERT_EQ(sizes.size(), 2u) << setting;
        const StudyRow &point = *sizes.at(0.0), &area = *sizes.at(0.6);
        // hard and msm4 with a fixed kernel do not read the light's size: the same image ...
        EXPECT_EQ(point.imageDigest, area.imageDigest) << setting;
        // ... and the same exact filtered visibility, but another ray-traced truth.
        EXPECT_EQ(point.filtered.rmse, area.filtered.rmse) << setting;
        EXPECT_NE(point.truth.rmse, area.truth.rmse)
            << setting << ": the area light's rows were scored against the point light's truth";
    }
    EXPECT_TRUE(fs::exists(*base_ / "one" / "truth" / "light_0.6" / "truth.png"));
}

}  // namespace
}  // namespace sl
