// test_bench_report: what `shadowlab bench` reports, checked on a tiny texture: a stubbed stage
// says "not implemented" (no ✓), an implemented one gets a ratio with its spread and a
// verdict against the goal, every row measured in copies is also put against the tiled copy
// (the right baseline, as many passes of it as of the copy), and --json carries the same rows
// and fields. No speed is asserted here:
// timings belong to the Bench* suites (CTest label `bench`, run by `./kit bench`).
#include "filter_benchmark.h"
#include "gl_test_support.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <regex>
#include <set>

namespace sl {
namespace {

const BenchRow* findRow(const BenchReport& report, const std::string& name) {
    for (const auto& row : report.rows)
        if (row.name == name) return &row;
    return nullptr;
}

// wide_blur shrunk to a 64² map seen by a 32² camera: the lighting row in milliseconds.
fs::path tinySatScene() {
    auto scene = nlohmann::json::parse(std::ifstream(test::scenePath("wide_blur")));
    scene["shadow"]["mapSize"] = 64;
    scene["shadow"]["filter"]["kernel"] = 5.5;
    scene["camera"]["width"] = 32;
    scene["camera"]["height"] = 32;
    scene.erase("expect");
    const fs::path path = test::tempDir("bench_lighting") / "tiny_sat.json";
    std::ofstream(path) << scene.dump(1);
    return path;
}

TEST(FilterBenchmark, SatLookupLightingRowSaysNotImplementedForAStubbedLookup) {
    test::sharedContext();
    const fs::path scene = tinySatScene();
    // The reference's sat.comp with the student's stubbed sat_lookup.glsl: the table is
    // fine, the lookup is not, and the lighting row must not be timed against its goal.
    Renderer mixed(ShaderLibrary::mixed(resolveSolution("reference"),
                                        {{"sat_lookup.glsl", resolveSolution("student")}},
                                        test::root()));
    BenchReport report = runFilterBenchmark(mixed, BenchOptions{32, 3, scene.string()});
    const BenchRow* row = findRow(report, "sat lookup, box 2, lighting pass (tiny_sat)");
    ASSERT_NE(row, nullptr) << formatBenchReport(report);
    EXPECT_FALSE(row->implemented);
    EXPECT_EQ(benchVerdict(*row), "not implemented");
    EXPECT_TRUE(findRow(report, "sat, rows + columns")->implemented);

    // The reference: timed, against the bilinear fetch, with the 3.4 goal and its spread.
    Renderer reference(test::library("reference"));
    report = runFilterBenchmark(reference, BenchOptions{32, 3, scene.string()});
    row = findRow(report, "sat lookup, box 2, lighting pass (tiny_sat)");
    ASSERT_NE(row, nullptr) << formatBenchReport(report);
    EXPECT_TRUE(row->implemented);
    EXPECT_EQ(row->baseline, "bilinear fetch");
    EXPECT_DOUBLE_EQ(row->goal, 3.4);
    EXPECT_LE(row->ratioMin, row->ratio);
    EXPECT_LE(row->ratio, row->ratioMax);
    EXPECT_NE(benchVerdict(*row), "not implemented");
    // The largest box against the smallest, in the same repeats, with the 1.1 goal.
    row = findRow(report, "sat lookup, box 512 / box 2, lighting pass");
    ASSERT_NE(row, nullptr) << formatBenchReport(report);
    EXPECT_EQ(row->baseline, "sat lookup, box 2");
    EXPECT_DOUBLE_EQ(row->goal, 1.1);
    EXPECT_LE(row->ratioMin, row->ratio);
    EXPECT_LE(row->ratio, row->ratioMax);
}

TEST(FilterBenchmark, StubStagesAreNotImplementedAndGetNoVerdict) {
    test::sharedContext();
    Renderer renderer(test::library("student"));
    const BenchReport report = runFilterBenchmark(renderer, 32, 3);
    for (const char* name : {"gaussian r=8, x", "gaussian r=16, y", "sat, rows + columns"}) {
        const BenchRow* row = findRow(report, name);
        ASSERT_NE(row, nullptr) << name;
        EXPECT_FALSE(row->implemented) << name;
        EXPECT_EQ(benchVerdict(*row), "not implemented") << name;
    }
    const std::string table = formatBenchReport(report);
    EXPECT_NE(table.find("| gaussian r=8, x |"), std::string::npos) << table;
    EXPECT_EQ(table.find("✓"), std::string::npos) << table;  // nothing stubbed passes
}

// Each filter's stub is found in what that filter writes: a stubbed sat.comp beside a solved
// Gaussian (whose output holds no -1) is still "not implemented", and the other way round.
TEST(FilterBenchmark, EachFilterIsCheckedInItsOwnOutput) {
    test::sharedContext();
    for (const char* stub : {"sat.comp", "gaussian_blur.comp"}) {
        Renderer mixed(ShaderLibrary::mixed(resolveSolution("reference"), {{stub, resolveSolution("student")}},
                                            test::root()));
        const BenchReport report = runFilterBenchmark(mixed, 32, 3);
        const bool satStub = std::string(stub) == "sat.comp";
        EXPECT_EQ(findRow(report, "sat, rows + columns")->implemented, !satStub) << stub;
        EXPECT_EQ(findRow(report, "gaussian r=8, x")->implemented, satStub) << stub;
        EXPECT_EQ(benchVerdict(*findRow(report, satStub ? "sat, rows + columns" : "gaussian r=16, y")),
                  "not implemented") << stub;
    }
}

TEST(FilterBenchmark, ImplementedStagesGetRatioSpreadAndGoal) {
    test::sharedContext();
    Renderer renderer(test::library("reference"));
    const BenchReport report = runFilterBenchmark(renderer, 32, 3);
    ASSERT_EQ(report.rows.front().name, "copy");
    for (const auto& row : report.rows) {
        EXPECT_TRUE(row.implemented) << row.name;
        EXPECT_LE(row.ratioMin, row.ratio) << row.name;
        EXPECT_LE(row.ratio, row.ratioMax) << row.name;
        EXPECT_GT(row.medianMs, 0.0) << row.name;
    }
    // The goals of docs/performance.md, in instructions: checked on that clock only (this
    // test runs on the CPU clock), and there the verdict follows the ratio either way.
    EXPECT_DOUBLE_EQ(findRow(report, "gaussian r=8, y")->goal, 1.2);
    EXPECT_DOUBLE_EQ(findRow(report, "gaussian r=16, x")->goal, 1.55);
    EXPECT_DOUBLE_EQ(findRow(report, "sat, rows + columns")->goal, 1.85);
    BenchRow row = *findRow(report, "gaussian r=8, x");
    EXPECT_FALSE(row.goalChecked);
    row.ratio = 5.0;
    EXPECT_EQ(benchVerdict(row), "≤ 1.2 in instructions (--exact)");
    EXPECT_NE(formatBenchReport(report).find("./kit bench --exact"), std::string::npos);
    row.goalChecked = true;
    row.ratio = 1.19;
    EXPECT_EQ(benchVerdict(row), "✓ ≤ 1.2");
    row.ratio = 1.21;
    EXPECT_EQ(benchVerdict(row), "✗ 1.21 > 1.2");
    row.ratio = 1.2031;
    EXPECT_EQ(benchVerdict(row), "✗ 1.203 > 1.2");  // "1.20 > 1.2" would read as the goal
    BenchRow wide = *findRow(report, "gaussian r=16, y");
    wide.goalChecked = true;
    wide.ratio = 1.56;
    EXPECT_EQ(benchVerdict(wide), "✗ 1.56 > 1.55");  // two digits where the goal has them
    wide.ratio = 1.5504;
    EXPECT_EQ(benchVerdict(wide), "✗ 1.5504 > 1.55");
    wide.goalChecked = false, wide.otherCompiler = true;
    EXPECT_EQ(benchVerdict(wide), "≤ 1.55 on LLVM 15/19");
    // The goals hold where they were measured, and only there.
    EXPECT_EQ(goalsCompilerMismatch("llvmpipe (LLVM 15.0.6, 256 bits)"), "");
    EXPECT_EQ(goalsCompilerMismatch("llvmpipe (LLVM 19.1.7, 256 bits)"), "");
    for (const char* other : {"llvmpipe (LLVM 21.1.8, 256 bits)", "llvmpipe (LLVM 15.0.6, 128 bits)",
                              "softpipe"})
        EXPECT_NE(goalsCompilerMismatch(other).find(other), std::string::npos) << other;

    const auto json = nlohmann::json::parse(benchReportJson(report));
    ASSERT_EQ(json["rows"].size(), report.rows.size());
    const auto& first = json["rows"][1];
    EXPECT_EQ(first["pass"], report.rows[1].name);
    for (const char* key : {"ratio", "ratioMin", "ratioMax", "goal", "goalChecked", "implemented", "verdict",
                            "tileBaselineMs", "tileRatio"})
        EXPECT_TRUE(first.contains(key)) << key;
}

// The goals the docs quote are the bench's own (one source: the goals in filter_benchmark.cpp):
// the handout's goal for the student's Gaussian and performance.md's table of goals. The
// measured figure both give for 8×8 groups is performance.md's, in one form.
TEST(FilterBenchmark, DocsQuoteTheBenchsGoals) {
    test::sharedContext();
    Renderer renderer(test::library("reference"));
    const BenchReport report =
        runFilterBenchmark(renderer, BenchOptions{16, 3, tinySatScene().string()});
    auto goal = [&](const std::string& name) {
        for (const auto& row : report.rows)
            if (row.name.rfind(name, 0) == 0) return row.goal;
        ADD_FAILURE() << "no bench row " << name << "\n" << formatBenchReport(report);
        return -1.0;
    };
    auto flat = [](const char* doc) {  // the doc's text with every run of white space one space
        return std::regex_replace(test::readFile(test::root() / doc), std::regex(R"(\s+)"), " ");
    };
    const std::string handout = flat("docs/handout.md"), perf = flat("docs/performance.md");
    const std::string num = R"(([0-9]+(?:\.[0-9]+)?))", range = R"(([0-9.]+–[0-9]+(?:\.[0-9]+)?))";
    std::smatch m;
    ASSERT_TRUE(std::regex_search(handout, m, std::regex(
        "the goal it checks is " + num + "× a copy per pass at r = 8, along x and along y \\(" +
        num + "× at r = 16\\)")))
        << "docs/handout.md no longer quotes the Gaussian's goal in the form this test reads";
    EXPECT_DOUBLE_EQ(std::stod(m[1]), goal("gaussian r=8, x"));
    EXPECT_DOUBLE_EQ(std::stod(m[1]), goal("gaussian r=8, y"));
    EXPECT_DOUBLE_EQ(std::stod(m[2]), goal("gaussian r=16, x"));
    EXPECT_DOUBLE_EQ(std::stod(m[2]), goal("gaussian r=16, y"));
    // No other goal for one direction only ("1.5× along y").
    EXPECT_FALSE(std::regex_search(handout, std::regex(num + "× (a copy )?along [xy]")))
        << "docs/handout.md states a goal per direction";

    // performance.md's goal table: one row per goal, each the bench's.
    int rows = 0;
    const std::regex perfRow(
        R"(\| (Gaussian r = (\d+), ([xy])|SAT, rows \+ columns|SAT lookup, lighting pass|SAT lookup, box 512 / box 2): ≤ )" +
        num + " \\|");
    for (std::sregex_iterator it(perf.begin(), perf.end(), perfRow), end; it != end; ++it, ++rows) {
        const auto& r = *it;
        const std::string pass = r[2].matched
            ? "gaussian r=" + r[2].str() + ", " + r[3].str()
            : r[1] == "SAT, rows + columns"       ? "sat, rows + columns"
            : r[1] == "SAT lookup, lighting pass" ? "sat lookup, box 2,"
                                                  : "sat lookup, box 512 / box 2";
        EXPECT_DOUBLE_EQ(std::stod(r[4]), goal(pass)) << "docs/performance.md: " << r[0];
    }
    EXPECT_EQ(rows, 7) << "docs/performance.md's table of goals";

    // 8×8 groups against 64×1: the same measured figures wherever they are quoted.
    const std::regex groups("costs? " + range + " copies at r = 8 instead of " + range);
    std::set<std::string> quoted;
    for (const std::string* doc : {&handout, &perf}) {
        std::sregex_iterator it(doc->begin(), doc->end(), groups), end;
        EXPECT_NE(it, end) << (doc == &perf ? "performance.md" : "handout.md") << ": no 8×8 figure";
        for (; it != end; ++it) quoted.insert((*it)[1].str() + " / " + (*it)[2].str());
    }
    EXPECT_EQ(quoted.size(), 1u) << testing::PrintToString(quoted);
}

// The tiled copy's row, found by its name "copy, N texels per invocation".
const BenchRow* tileCopyRow(const BenchReport& report) {
    return findRow(report, "copy, " + std::to_string(report.tileCopyTexels) +
                               " texels per invocation");
}

TEST(FilterBenchmark, EveryCopyMeasuredRowIsAlsoAgainstTheTiledCopy) {
    test::sharedContext();
    Renderer renderer(test::library("reference"));
    const BenchReport report = runFilterBenchmark(renderer, 32, 3);
    ASSERT_GT(report.tileCopyTexels, 1);
    const BenchRow* tile = tileCopyRow(report);
    ASSERT_NE(tile, nullptr) << formatBenchReport(report);
    ASSERT_EQ(&report.rows[1], tile);  // the second floor, right under the copy
    const BenchRow& copy = report.rows[0];
    EXPECT_DOUBLE_EQ(copy.medianMs, report.copyMedianMs);
    EXPECT_DOUBLE_EQ(tile->medianMs, report.tileCopyMedianMs);
    // The tiled copy against the copy (verdict's column) and against itself.
    EXPECT_EQ(tile->baseline, "copy");
    EXPECT_DOUBLE_EQ(tile->ratio, report.tileCopyMedianMs / report.copyMedianMs);
    EXPECT_DOUBLE_EQ(tile->tileRatio, 1.0);
    EXPECT_DOUBLE_EQ(copy.tileRatio, report.copyMedianMs / report.tileCopyMedianMs);
    // Each filter row: the verdict's ratio against `copies` copies, the tiled one against as
    // many tiled copies (the SAT row against two of each).
    for (const char* name : {"gaussian r=4, x", "gaussian r=8, y", "gaussian r=16, x",
                             "sat, rows + columns"}) {
        const BenchRow* row = findRow(report, name);
        ASSERT_NE(row, nullptr) << name;
        const double copies = row->baseline == "2 copies" ? 2 : 1;
        EXPECT_DOUBLE_EQ(row->baselineMs, copies * report.copyMedianMs) << name;
        EXPECT_DOUBLE_EQ(row->tileBaselineMs, copies * report.tileCopyMedianMs) << name;
        EXPECT_DOUBLE_EQ(row->tileRatio, row->medianMs / row->tileBaselineMs) << name;
        EXPECT_DOUBLE_EQ(row->ratio, row->medianMs / row->baselineMs) << name;
    }
    EXPECT_EQ(findRow(report, "sat, rows + columns")->baseline, "2 copies");

    const auto json = nlohmann::json::parse(benchReportJson(report));
    EXPECT_EQ(json["tileCopyTexels"], report.tileCopyTexels);
    EXPECT_DOUBLE_EQ(json["tileCopyMs"].get<double>(), report.tileCopyMedianMs);
    EXPECT_DOUBLE_EQ(json["copyMs"].get<double>(), report.copyMedianMs);
    for (size_t i = 0; i < report.rows.size(); ++i) {
        EXPECT_DOUBLE_EQ(json["rows"][i]["tileRatio"].get<double>(), report.rows[i].tileRatio)
            << report.rows[i].name;
        EXPECT_DOUBLE_EQ(json["rows"][i]["tileBaselineMs"].get<double>(),
                         report.rows[i].tileBaselineMs)
            << report.rows[i].name;
    }
}

// The table's last column is the tiled ratio, "–" for a row not measured in copies; JSON null.
TEST(FilterBenchmark, TableAndJsonCarryTheTiledRatioColumn) {
    BenchReport report;
    report.size = 32;
    report.repeats = 3;
    report.copyMedianMs = 2.0;
    report.tileCopyMedianMs = 1.0;
    report.tileCopyTexels = 4;
    const BenchRow gaussian{.name = "gaussian r=8, x", .medianMs = 1.5, .baselineMs = 2.0,
                            .ratio = 0.75, .ratioMin = 0.7, .ratioMax = 0.8, .goal = 1.3,
                            .goalChecked = true, .baseline = "copy", .tileBaselineMs = 1.0, .tileRatio = 1.5};
    const BenchRow lighting{.name = "sat lookup, lighting pass (x)", .medianMs = 3.0,
                            .baselineMs = 3.0, .ratio = 1.0, .ratioMin = 1.0, .ratioMax = 1.0,
                            .goal = 1.2, .goalChecked = true, .baseline = "bilinear fetch"};
    report.rows = {gaussian, lighting};

    const std::string table = formatBenchReport(report);
    EXPECT_NE(table.find("| pass | median ms | baseline | ratio | spread | goal | tiled |"),
              std::string::npos) << table;
    EXPECT_NE(table.find("| gaussian r=8, x | 1.50 | copy | 0.75 | 0.70–0.80 | ✓ ≤ 1.3 | 1.50 |"),
              std::string::npos) << table;
    EXPECT_NE(table.find("| bilinear fetch | 1.00 | 1.00–1.00 | ✓ ≤ 1.2 | – |"),
              std::string::npos) << table;
    EXPECT_NE(table.find("4-texel copy"), std::string::npos) << table;

    const auto json = nlohmann::json::parse(benchReportJson(report));
    EXPECT_DOUBLE_EQ(json["rows"][0]["tileRatio"].get<double>(), 1.5);
    EXPECT_TRUE(json["rows"][1]["tileRatio"].is_null());
    EXPECT_TRUE(json["rows"][1]["tileBaselineMs"].is_null());
}

// Copy passes far apart over the repeats: the table says the machine was busy (and JSON holds
// the copy's fastest and slowest repeat); close together: no such line.
TEST(FilterBenchmark, ABusyMachineIsSaidUnderTheTable) {
    BenchReport report{.size = 32, .repeats = 3, .copyMedianMs = 6.0, .copyMinMs = 5.0,
                       .copyMaxMs = 9.0,
                       .rows = {{.name = "copy", .medianMs = 6.0, .baselineMs = 6.0, .ratio = 1.0,
                                 .ratioMin = 1.0, .ratioMax = 1.0, .baseline = "copy"}}};
    const std::string busy = formatBenchReport(report);
    EXPECT_NE(busy.find("busy machine: the copy pass took 5.00–9.00 ms"), std::string::npos) << busy;
    const auto json = nlohmann::json::parse(benchReportJson(report));
    EXPECT_DOUBLE_EQ(json["copyMinMs"].get<double>(), 5.0);
    EXPECT_DOUBLE_EQ(json["copyMaxMs"].get<double>(), 9.0);
    report.copyMaxMs = 6.5;
    const std::string quiet = formatBenchReport(report);
    EXPECT_EQ(quiet.find("busy machine"), std::string::npos) << quiet;
}

TEST(FilterBenchmark, CommandPrintsJsonWhenAskedWithoutAFile) {
    auto r = test::runCommand(test::shadowlabBinary() +
                              " bench --size 32 --repeats 3 --lighting-scene none --json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto json = nlohmann::json::parse(r.output.substr(r.output.find('{')));
    EXPECT_EQ(json["size"], 32);
    EXPECT_EQ(json["rows"][0]["pass"], "copy");
    EXPECT_EQ(json["rows"][1]["pass"], "copy, " + std::to_string(json["tileCopyTexels"].get<int>()) +
                                           " texels per invocation");
}

}  // namespace
}  // namespace sl
