// A student can reproduce every failing case (a grade must be fair and explainable): probe
// sat-lookup prints the exact box means next to the solution's and says whether the box sits on
// texel centres; the box set fits any --map-size; the robustness stage's zf ladder and the moments
// stage's relativeDepth ladder can be written with `probe --generate`.
#include "depth_ladder.h"
#include "gl_test_support.h"
#include "probe_cases.h"

#include <fstream>
#include <sstream>

namespace sl {
namespace {

int column(const std::vector<std::string>& header, const std::string& name) {
    for (size_t i = 0; i < header.size(); ++i)
        if (header[i] == name) return int(i);
    ADD_FAILURE() << "no column " << name;
    return 0;
}

TEST(FairnessProbe, SatLookupPrintsExpectedValuesForBoxesThatFitAnyMapSize) {
    const fs::path dir = test::tempDir("fairness_probe_sat");
    const std::string bin = test::shadowlabBinary();
    for (int n : {100, 37}) {
        SCOPED_TRACE(n);
        const fs::path boxes = dir / ("boxes" + std::to_string(n) + ".csv"),
                       out = dir / ("out" + std::to_string(n) + ".csv");
        auto gen = test::runCommand(bin + " probe sat-lookup --generate boxes --map-size " +
                                    std::to_string(n) + " --out " + boxes.string());
        ASSERT_EQ(gen.exitCode, 0) << gen.output;
        auto run = test::runCommand(bin + " probe sat-lookup --solution reference --map-size " +
                                    std::to_string(n) + " --input " + boxes.string() + " --out " + out.string());
        ASSERT_EQ(run.exitCode, 0) << run.output;
        const auto rows = test::readCsv(out);
        ASSERT_GT(rows.size(), 20u);
        const auto& h = rows[0];
        const int cx = column(h, "cx"), w = column(h, "w"), err = column(h, "max_error"),
                  centres = column(h, "texel_centres"), b1 = column(h, "b1"), e1 = column(h, "expected_b1");
        int crossing = 0, fractional = 0, offCentre = 0;
        for (size_t r = 1; r < rows.size(); ++r) {
            const double x = std::stod(rows[r][size_t(cx)]), size = std::stod(rows[r][size_t(w)]);
            EXPECT_GE(x, 0.0);
            EXPECT_LE(x, double(n)) << "a box centre outside the map";
            crossing += x - 0.5 * size < 0 || x + 0.5 * size > n;
            fractional += size != std::floor(size);
            offCentre += rows[r][size_t(centres)] == "no";
            // The reference meets the handout's 1e-4 on every box, and the columns agree.
            EXPECT_LE(std::stod(rows[r][size_t(err)]), 1e-4) << r;
            EXPECT_NEAR(std::stod(rows[r][size_t(b1)]), std::stod(rows[r][size_t(e1)]), 1e-4) << r;
        }
        EXPECT_GT(crossing, 0) << "boxes across the map's border";
        EXPECT_GT(fractional, 0) << "fractional box sizes";
        EXPECT_GT(offCentre, 0) << "boxes off texel centres, marked as such";
    }
}

TEST(FairnessProbe, LaddersOfTheGraderCanBeGenerated) {
    const std::string bin = test::shadowlabBinary();
    const fs::path dir = test::tempDir("fairness_probe_ladders");
    // The robustness stage's zf ladder: every hard case at its 50 fragment depths.
    auto zf = test::runCommand(bin + " probe msm --generate zf-ladder --out " + (dir / "zf.csv").string());
    ASSERT_EQ(zf.exitCode, 0) << zf.output;
    const auto zrows = test::readCsv(dir / "zf.csv");
    EXPECT_EQ(zrows.size(), 1 + msmHardCaseCatalogue().size() * 50);
    // The moments stage's relativeDepth ladder, with depths outside [near, far].
    auto d = test::runCommand(bin + " probe moments --generate depth-ladder --out " + (dir / "d.csv").string());
    ASSERT_EQ(d.exitCode, 0) << d.output;
    auto p = test::runCommand(bin + " probe moments --solution reference --input " +
                              (dir / "d.csv").string() + " --out " + (dir / "dout.csv").string());
    ASSERT_EQ(p.exitCode, 0) << p.output;
    const auto rows = test::readCsv(dir / "dout.csv");
    ASSERT_EQ(rows.size(), 1 + relativeDepthLadder().size());
    const int depth = column(rows[0], "lightDepth"), nearC = column(rows[0], "near"),
              farC = column(rows[0], "far"), b1 = column(rows[0], "b1"), e1 = column(rows[0], "expected_b1");
    int outside = 0;
    for (size_t r = 1; r < rows.size(); ++r) {
        const double z = std::stod(rows[r][size_t(depth)]);
        outside += z < std::stod(rows[r][size_t(nearC)]) || z > std::stod(rows[r][size_t(farC)]);
        EXPECT_NEAR(std::stod(rows[r][size_t(b1)]), std::stod(rows[r][size_t(e1)]), 1e-6) << r;
    }
    EXPECT_GE(outside, int(relativeDepthLadder().size()) / 3);
}

}  // namespace
}  // namespace sl
