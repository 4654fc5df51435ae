// test_bench_filters: the speed goals of docs/performance.md as a benchmark (suite names
// Bench*: CTest label `bench`, run by `./kit bench`, never by `./kit test`). Ratios to a copy
// pass measured in the same run, 1024² RGBA32F, medians of interleaved repeats; the whole
// table is printed, so a failure shows where the time went. On a loaded machine re-run it.
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
        options.size = 1024;
        options.repeats = 21;
        options.lightingScene = test::scenePath("wide_blur").string();
        BenchReport r = runFilterBenchmark(renderer, options);
        std::printf("%s", formatBenchReport(r).c_str());
        return r;
    }();
    return report;
}

void expectGoal(const std::string& name) {
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
