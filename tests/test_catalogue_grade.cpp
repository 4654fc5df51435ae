// Level 2 of the catalogue (see test_catalogue.cpp): every entry through `shadowlab grade`.
#include "catalogue_entries.h"
#include "kit_test_support.h"

#include <unistd.h>

namespace sl {
namespace {

// ------------------------------------------------------------------ level 2: the grader

bool graderBuilt() {
    static const bool built = [] {
        test::CommandResult r = test::runCommand(test::shadowlabBinary() + " grade --help");
        return r.exitCode == 0 && r.output.find("--submission") != std::string::npos;
    }();
    return built;
}

struct StageScore {
    double score = 0.0, max = 0.0;
    std::string output;
    bool full() const { return score >= max - 1e-9; }
};

// Per stage tag ("stage:<stage>"), the scores of one results.json, summed over its tests.
std::map<std::string, StageScore> stageScores(const json& results) {
    std::map<std::string, StageScore> stages;
    for (const json& t : results["tests"]) {
        std::string stage;
        if (t.contains("tags"))
            for (const json& tag : t["tags"]) {
                const std::string s = tag.get<std::string>();
                if (s.rfind("stage:", 0) == 0) stage = s.substr(6);
            }
        if (stage.empty()) continue;
        stages[stage].score += t.value("score", 0.0);
        stages[stage].max += t.value("max_score", 0.0);
        stages[stage].output += t.value("output", "");
    }
    return stages;
}

// Every entry's points per stage against the committed goldens, as graded on the goldens' own
// renderer: the grade every other machine must give too.
constexpr const char* kScoresFile = "catalogue_scores.json";
// How far a score inside its ramp may move on another renderer: Mesa 25.0.7 (LLVM 19) and
// 26.1.6 (LLVM 21) moved the same 6 of the 52 entries by the same amounts, at most 0.03 points
// (of 100), all mutants inside a ramp.
constexpr double kOtherRendererPoints = 0.1;

// Whether this machine renders as the goldens' did (the manifest's Mesa version and renderer,
// which names LLVM and the vector width): there a live reference gives the goldens' values.
bool onTheGoldensRenderer() {
    const json manifest = json::parse(std::ifstream(test::root() / "scenes/goldens/manifest.json"));
    const ContextInfo& info = test::sharedContext().info();
    return manifest.value("mesa_version", "") == info.mesaVersion &&
           manifest.value("renderer", "") == info.renderer;
}

// The references the catalogue is graded against, each a whole batch: the committed goldens
// (what the student kit's self-check and the Gradescope zip grade against, on every Mesa) and,
// where this machine renders as the goldens' did, the live reference too, whose stage scores
// must then equal the goldens' entry by entry. SHADOWLAB_CATALOGUE_REFERENCE=live|golden grades
// against that one only.
std::vector<std::string> referenceModes() {
    if (const char* mode = std::getenv("SHADOWLAB_CATALOGUE_REFERENCE"); mode && *mode)
        return {mode};
    if (onTheGoldensRenderer()) return {"golden", "live"};
    return {"golden"};
}

// Every entry grouped by its first scene (the catalogue lists first a scene where the bug shows).
std::map<std::string, std::vector<const Entry*>> entriesByScene() {
    std::map<std::string, std::vector<const Entry*>> byScene;
    for (const Entry& e : catalogue())
        if (!e.scenes.empty()) byScene[e.scenes.front()].push_back(&e);
    return byScene;
}

// A batch folder of complete submissions: the reference's five files with each entry's on top
// (a folder with the one file alone would, rightly, grade the other stages "not submitted").
void writeBatch(const fs::path& batch, const std::vector<const Entry*>& entries) {
    for (const Entry* e : entries) {
        const fs::path submission = batch / e->name;
        fs::create_directories(submission);
        for (const auto& name : stageFileNames())
            fs::copy_file(repoRoot() / "reference" / name, submission / name,
                          fs::copy_options::overwrite_existing);
        for (const auto& file : e->files)
            fs::copy_file(Entry::submissionsDir() / file, submission / fs::path(file).filename(),
                          fs::copy_options::overwrite_existing);
    }
}

// `program grade --batch` of one scene's batch (`env` before it), each entry's stage points
// read back from its results.json (a missing one is a failure, and no row).
std::map<std::string, std::map<std::string, StageScore>> gradeBatch(
    const std::string& program, const fs::path& batch, const fs::path& out, const std::string& scene,
    const std::string& mode, const std::vector<const Entry*>& entries, const std::string& env = "") {
    const auto start = std::chrono::steady_clock::now();
    const test::CommandResult run = test::runCommand(
        env + (env.empty() ? "" : " ") + program + " grade --batch '" + batch.string() + "' --out '" +
        out.string() + "' --scenes " + scene + " --reference " + mode + " --no-report -j 2 --timeout 120");
    std::printf("[catalogue] grade --batch of %zu entries on %s against %s: %.1f s, exit %d\n",
                entries.size(), scene.c_str(), mode.c_str(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                run.exitCode);
    std::map<std::string, std::map<std::string, StageScore>> scores;
    for (const Entry* e : entries) {
        std::ifstream in(out / e->name / "results.json");
        const json results = in ? json::parse(in, nullptr, false) : json();
        if (!results.is_object() || !results.contains("tests")) {
            ADD_FAILURE() << e->name << ": no results.json with tests[]; exit " << run.exitCode << "\n"
                          << run.output;
            continue;
        }
        scores[e->name] = stageScores(results);
    }
    return scores;
}

// The committed table's points for `entry`, checked against what was graded: exact on the
// goldens' renderer; elsewhere a score strictly inside its stage's ramp moves with the pixels
// (the ramp is continuous) and may differ by kOtherRendererPoints, while at full marks and at
// zero it may not, so every stage's verdict is the same.
void expectTheTablesPoints(const json& expected, const Entry& e,
                           const std::map<std::string, StageScore>& stages, bool sameRenderer) {
    if (!expected.contains(e.name)) {
        ADD_FAILURE() << "no row in " << kScoresFile << ": remake it (docs/catalogue.md)";
        return;
    }
    for (const auto& [stage, s] : stages) {
        const double want = expected[e.name].value(stage, -1.0);
        const bool inside = want > 1e-9 && want < s.max - 1e-9;
        EXPECT_NEAR(s.score, want, sameRenderer || !inside ? 1e-9 : kOtherRendererPoints)
            << "stage " << stage << ": not the points of " << kScoresFile
            << " (graded on the goldens' renderer)\n" << s.output;
    }
}

json expectedTable() {
    const fs::path table = Entry::submissionsDir() / kScoresFile;
    return fs::exists(table) ? json::parse(std::ifstream(table)) : json::object();
}

// Every entry through `shadowlab grade`. Each entry is a complete submission: the reference's
// five files with the entry's file(s) on top (a folder with the one file alone would, rightly,
// grade the other stages "not submitted"). Graded on its first scene (the catalogue lists
// first a scene where the bug shows), against the live reference, without the HTML report,
// as one --batch per scene: one process for all entries (~40-80 s for the 30 entries on 2
// busy cores, against ~3 min for 30 single `grade --submission` runs). --timeout 120: a busy
// shared machine must not turn a slow render into a "timed out" zero.
TEST(CatalogueGrade, MutantsLoseOnlyOnTheirStageAlternativesScoreFull) {
    if (!graderBuilt()) GTEST_SKIP() << "grader not built yet";
    // Per process: a concurrent run of the suite (several people share build/) must not
    // delete this one's folders.
    const fs::path dir = test::tempDir("catalogue_grade_" + std::to_string(getpid()));
    std::string finalLosses;  // alternatives that lose points on the end-to-end image only
    for (const Entry& e : catalogue()) ASSERT_FALSE(e.scenes.empty()) << e.name;
    const std::vector<std::string> modes = referenceModes();
    const bool sameRenderer = onTheGoldensRenderer();
    const json expected = expectedTable();
    json measured = json::object();
    std::map<std::string, std::map<std::string, StageScore>> first;  // per entry, the first mode's
    for (const auto& [scene, entries] : entriesByScene()) {
        const fs::path batch = dir / ("submissions_" + scene);
        writeBatch(batch, entries);
        for (const std::string& mode : modes) {
            const auto graded = gradeBatch(test::shadowlabBinary(), batch,
                                           dir / ("out_" + scene + "_" + mode), scene, mode, entries);
            for (const Entry* e : entries) {
                SCOPED_TRACE(e->name + " (" + e->kind + ", stage " + e->stage + ", scene " + scene +
                             ", reference " + mode + ")");
                if (!graded.count(e->name)) continue;
                const auto& stages = graded.at(e->name);
                EXPECT_TRUE(stages.count(e->stage)) << "no test tagged stage:" << e->stage;
                std::string table;
                for (const auto& [stage, s] : stages) {
                    char buf[96];
                    std::snprintf(buf, sizeof buf, "%s %.2f/%.2f  ", stage.c_str(), s.score, s.max);
                    table += buf;
                }
                std::printf("[catalogue] grade %-31s %-11s %-6s %s\n", e->name.c_str(), e->kind.c_str(),
                            mode.c_str(), table.c_str());
                // One grade on every machine: against the goldens, the committed table's points.
                if (mode == "golden") {
                    for (const auto& [stage, s] : stages) measured[e->name][stage] = s.score;
                    expectTheTablesPoints(expected, *e, stages, sameRenderer);
                }
                // One grade: every stage's points equal to the first reference's, to the digit.
                if (mode == modes.front()) first[e->name] = stages;
                else
                    for (const auto& [stage, s] : stages)
                        EXPECT_NEAR(s.score, first[e->name][stage].score, 1e-9)
                            << "stage " << stage << ": " << mode << " and " << modes.front()
                            << " give different points\n" << s.output << "\n---\n"
                            << first[e->name][stage].output;
                for (const auto& [stage, s] : stages) {
                    SCOPED_TRACE("stage " + stage + ": " + std::to_string(s.score) + " / " +
                                 std::to_string(s.max) + "\n" + s.output);
                    if (e->mutant()) {
                        // The end-to-end "final" stage may lose points too: not checked. Nor may
                        // "robustness" for an msm mutant: it probes the same msm.glsl.
                        const bool sameFile = e->stage == "msm" && stage == "robustness";
                        if (stage != e->stage && stage != "final" && !sameFile) {
                            EXPECT_TRUE(s.full()) << "a mutant must not lose points on another stage";
                        }
                    } else if (stage == "robustness" && e->stage == "msm" && e->robustnessReported) {
                        // Correct on every scene, yet a solve may be less stable on the adversarial
                        // hard cases (msm_cramer: non-monotone on 16 of 289): that is what the
                        // robustness stage is for, so it is reported, not required (catalogue.md).
                        if (!s.full()) std::printf("[catalogue] %s: robustness %.2f / %.2f\n",
                                                   e->name.c_str(), s.score, s.max);
                    } else if (stage != "final") {
                        EXPECT_TRUE(s.full()) << "an alternative must score full marks";
                    } else if (!s.full()) {
                        finalLosses += e->name + ": final " + std::to_string(s.score) + " / " +
                                       std::to_string(s.max) + " on " + scene + "; ";
                    }
                }
                if (e->mutant()) {
                    // A mutant loses on its own stage. msm.glsl is graded twice, on the scenes'
                    // images (msm) and on the hard cases (robustness), and either counts: a missing
                    // moment bias is off on 12 hard cases on every Mesa and against the goldens,
                    // while on classic's images it is a margin case (97.3 % against the ramp's 98 %,
                    // live on Mesa 22.3.6; full against the goldens on Mesa 25.0.7).
                    const auto lost = [&](const std::string& stage) {
                        return stages.count(stage) && !stages.at(stage).full();
                    };
                    EXPECT_TRUE(lost(e->stage) || (e->stage == "msm" && lost("robustness")))
                        << "a mutant must lose points on its own stage";
                }
            }
        }
    }
    // SHADOWLAB_CATALOGUE_SCORES=FILE writes what was measured against the goldens (on the
    // goldens' renderer, the committed table: docs/catalogue.md).
    if (const char* out = std::getenv("SHADOWLAB_CATALOGUE_SCORES"); out && *out && !measured.empty())
        std::ofstream(out) << measured.dump(1) << "\n";
    if (!HasFailure()) fs::remove_all(dir);  // kept for inspection when something failed
    if (!finalLosses.empty() && !HasFailure()) {
        // Every isolated stage passed. What is left is for the grader to fix: through a SAT,
        // the end-to-end shadow is chaotic in float rounding. Even sat_lookup_fp_order (box
        // means within 2e-5 of the reference's) flips G by up to 0.99 on 1-3 % of the contact
        // and wide_blur pixels, so "final" cannot ask for 99.5 % of the pixels within
        // tolerance of the reference there. (docs/catalogue.md, "Known grader issue".)
        GTEST_SKIP() << "known grader issue: correct alternatives lose points on the end-to-end "
                        "final image only (every isolated stage scores as required): "
                     << finalLosses;
    }
}

// The self-check is the autograder's grade: every entry graded by the packed student kit's
// own program (built from the tarball, no reference/, its own goldens) gets the committed table's
// points, the autograder's (the full kit against the goldens; live on the goldens' renderer,
// which the test above shows equal).
TEST(CatalogueGrade, ThePackedStudentKitGradesEveryEntryAsTheAutograder) {
    if (!graderBuilt()) GTEST_SKIP() << "grader not built yet";
    const fs::path dir = test::tempDir("catalogue_student_kit_" + std::to_string(getpid()));
    const auto unpacked = test::unpackStudentKit(dir);
    ASSERT_EQ(unpacked.error, "");
    ASSERT_FALSE(fs::exists(unpacked.root / "reference"));
    auto build = test::buildKitProgram(unpacked.root);
    ASSERT_EQ(build.exitCode, 0) << build.output;
    const std::string program = (unpacked.root / "build/shadowlab").string();
    const json expected = expectedTable();
    const bool sameRenderer = onTheGoldensRenderer();
    for (const auto& [scene, entries] : entriesByScene()) {
        const fs::path batch = dir / ("submissions_" + scene);
        writeBatch(batch, entries);
        // --reference golden said, though the student kit's auto means it too.
        const auto graded = gradeBatch(program, batch, dir / ("out_" + scene), scene, "golden", entries,
                                       "env -u SHADOWLAB_ROOT -u SHADOWLAB_BUILD");
        for (const Entry* e : entries) {
            SCOPED_TRACE(e->name + " (" + e->kind + ", scene " + scene + ", the student kit)");
            if (graded.count(e->name)) expectTheTablesPoints(expected, *e, graded.at(e->name), sameRenderer);
        }
    }
    if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
}  // namespace sl
