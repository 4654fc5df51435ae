// test_bench_filters: the speed goals of docs/performance.md as a benchmark (suite names
// Bench*: CTest label `bench`, never run by `./kit test`). The goals are ratios of
// instructions, so the suite runs on the exact clock (`./kit bench --exact` runs it under
// tools/cost_exact.sh) and skips on the CPU clock; ratios to a copy pass in the same run,
// 256² RGBA32F; the whole table is printed, so a failure shows where the work went.
#include "cost_clock.h"
#include "filter_benchmark.h"
#include "gl_test_support.h"

#include <cstdio>

namespace sl {
namespace {

const BenchReport& referenceReport() {
    static const BenchReport report = [] {
        test::sharedContext();
        Renderer renderer(test::library("reference"));
        BenchOptions options;
        options.size = 256;  // instructions per texel hardly depend on the size
        options.repeats = 3;  // the exact clock gives every repeat the same figure
        options.lightingScene = test::scenePath("wide_blur").string();
        BenchReport r = runFilterBenchmark(renderer, options);
        std::printf("%s", formatBenchReport(r).c_str());
        return r;
    }();
    return report;
}

void expectGoal(const std::string& name) {
    if (!costCountsInstructions())
        GTEST_SKIP() << "the goals are ratios of instructions: ./kit bench --exact (or "
                        "tools/cost_exact.sh build/tests/shadowlab_tests --gtest_filter='Bench*')";
    for (const auto& row : referenceReport().rows)
        if (row.name.rfind(name, 0) == 0) {
            EXPECT_LE(row.ratio, row.goal) << row.name << ": " << row.ratio << " (spread "
                                           << row.ratioMin << "–" << row.ratioMax << ")";
            return;
        }
    ADD_FAILURE() << "no row " << name;
}

TEST(BenchFilters, GaussianRadius8WithinGoalBothDirections) {
    expectGoal("gaussian r=8, x");
    expectGoal("gaussian r=8, y");
}

TEST(BenchFilters, GaussianRadius16WithinGoalBothDirections) {
    expectGoal("gaussian r=16, x");
    expectGoal("gaussian r=16, y");
}

TEST(BenchFilters, SatBothPassesWithinGoal) { expectGoal("sat, rows + columns"); }

TEST(BenchFilters, SatLookupLightingPassWithinGoal) { expectGoal("sat lookup, box 2,"); }

// The table's point: the lookup costs the same for any box (largest box / smallest).
TEST(BenchFilters, SatLookupFlatInTheBoxSize) { expectGoal("sat lookup, box 512 / box 2"); }

}  // namespace
}  // namespace sl
