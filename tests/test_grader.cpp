// The grader (docs/grading.md): full marks for the reference, live and against the goldens;
// zero with "not implemented" for the stubs; a valid results.json in every case, even when the
// grader itself cannot run; the report opens in a browser; batch grading writes scores.csv.
#include "test_grader_support.h"

#include <set>

namespace sl {
namespace {

void expectGradescopeFormat(const nlohmann::json& r) {
    ASSERT_TRUE(r.is_object()) << r;
    EXPECT_TRUE(r["score"].is_number());
    EXPECT_TRUE(r["execution_time"].is_number());
    EXPECT_TRUE(r["output"].is_string());
    ASSERT_TRUE(r["tests"].is_array());
    for (const auto& t : r["tests"]) {
        for (const char* k : {"name", "output", "visibility", "status"}) EXPECT_TRUE(t[k].is_string()) << k;
        EXPECT_TRUE(t["score"].is_number());
        EXPECT_TRUE(t["max_score"].is_number());
        EXPECT_TRUE(t["status"] == "passed" || t["status"] == "failed");
        ASSERT_EQ(t["tags"].size(), 2u);
        EXPECT_EQ(t["tags"][0].get<std::string>().rfind("stage:", 0), 0u);
        EXPECT_EQ(t["tags"][1].get<std::string>().rfind("scene:", 0), 0u);
    }
}

}  // namespace

TEST(Grader, ReferenceScoresFullOnEveryStageLive) {
    fs::path out = test::tempDir("grader_reference_live");
    auto g = test::grade("--reference live --submission " + (test::root() / "reference").string(), out);
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    expectGradescopeFormat(g.results);
    EXPECT_DOUBLE_EQ(g.results["score"].get<double>(), 100.0) << g.run.output;
    std::set<std::string> stages;
    for (const auto& t : g.results["tests"]) {
        EXPECT_EQ(t["status"], "passed") << t;
        stages.insert(t["tags"][0].get<std::string>());
    }
    EXPECT_EQ(stages.size(), 6u);  // moments, gaussian, sat, msm, robustness, final
    EXPECT_NE(g.run.output.find("msm "), std::string::npos) << g.run.output;  // the table
    EXPECT_TRUE(fs::exists(out / "report" / "index.html"));
}

TEST(Grader, CommittedGoldensMatchALiveReferenceRender) {
    // Stale goldens (after a change to reference/ or a scene) must not pass silently. Remake:
    //   build/shadowlab golden --solution reference --out scenes/goldens
    const fs::path goldens = test::root() / "scenes" / "goldens";
    auto g = test::grade("--reference golden --scenes classic,contact --no-report --submission " +
                             (test::root() / "reference").string(),
                         test::tempDir("grader_reference_golden"));
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    EXPECT_DOUBLE_EQ(g.results["score"].get<double>(), 100.0) << g.run.output;
    // golden --check: the same pixels on the goldens' renderer, within the grading tolerance
    // on any other (golden_check.h).
    auto check = test::runCommand(test::shadowlabBinary() + " golden --check");
    EXPECT_EQ(check.exitCode, 0) << "goldens are stale; remake them with\n"
                                    "  build/shadowlab golden --solution reference --out scenes/goldens\n"
                                 << check.output;
    // The hidden scenes' goldens too (instructor kit only): they live beside their scene files.
    const fs::path hidden = test::root() / "scenes" / "hidden";
    std::string hiddenScenes;  // as --scenes takes them: one render for all
    if (fs::is_directory(hidden))
        for (const auto& f : fs::directory_iterator(hidden))
            if (f.path().extension() == ".json")
                hiddenScenes += (hiddenScenes.empty() ? "" : ",") + f.path().string();
    if (!hiddenScenes.empty()) {
        auto h = test::runCommand(test::shadowlabBinary() + " golden --check --scenes " + hiddenScenes);
        EXPECT_EQ(h.exitCode, 0) << "hidden goldens are stale; remake them with\n"
                                    "  build/shadowlab golden --solution reference --scenes "
                                 << hiddenScenes << "\n" << h.output;
    }
}

TEST(Grader, StudentStubsScoreZeroAsNotImplemented) {
    fs::path out = test::tempDir("grader_stubs");
    auto g = test::grade("--scenes classic,contact --submission " + (test::root() / "student").string(), out);
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    expectGradescopeFormat(g.results);
    EXPECT_EQ(g.results["score"].get<double>(), 0.0);
    // 2 scenes × (moments, filter, msm, final), and robustness once.
    ASSERT_EQ(g.results["tests"].size(), 9u);
    for (const auto& t : g.results["tests"]) {
        EXPECT_EQ(t["score"].get<double>(), 0.0) << t["name"];
        EXPECT_NE(t["output"].get<std::string>().find("not implemented"), std::string::npos) << t;
    }

    // The report opens in a browser and shows something. Its stub images are reduced previews
    // only: a full-size copy of an all-magenta image says nothing more. (Only the scouts'
    // images: the stub stages' other renders are not run, grade.cpp.)
    const fs::path page = out / "report" / "index.html";
    ASSERT_TRUE(fs::exists(page));
    int previews = 0;
    for (const auto& f : fs::directory_iterator(out / "report" / "img")) {
        EXPECT_EQ(f.path().filename().string().find("_full"), std::string::npos) << f.path();
        ++previews;
    }
    EXPECT_GE(previews, 6);  // reference, submission and heat-map of >= 2 images
    if (test::runCommand("command -v chromium").exitCode != 0)
        GTEST_SKIP() << "chromium is not installed (apt-get install chromium): report not opened";
    const fs::path shot = test::tempDir("grader_report_shot") / "shot.png";
    const fs::path profile = test::tempDir("grader_report_profile");
    auto r = test::screenshotPage(page, shot, profile, 1200, 2000);
    ASSERT_TRUE(fs::exists(shot)) << r.output;
    EXPECT_GT(test::colourSpread(shot), 0.05) << "the screenshot is (nearly) one colour: a blank page";
    EXPECT_GT(fs::file_size(shot), 20000u);
}

// Scouts (grade.cpp): a stage that is the stub everywhere is rendered once; its other scenes and
// the finals that use it score 0 unrendered. A stage that is implemented is never skipped.
TEST(Grader, StubStagesRenderOnceAndAnImplementedStageIsStillGradedEverywhere) {
    const fs::path out = test::tempDir("grader_scouts");
    const std::string scenes = " --scenes classic,contact,depth_range,wide_blur --reference golden --no-report --keep-work";
    auto stubs = test::grade("--submission " + (test::root() / "student").string() + scenes, out / "stubs");
    ASSERT_EQ(stubs.run.exitCode, 0) << stubs.run.output;
    // 4 scenes x (moments, filter, msm, final) + robustness = 17 tests; renders: the robustness
    // test, one moments, one Gaussian and one SAT render, and at most one more per stage that
    // started before its scout had ended (two run at a time).
    ASSERT_EQ(stubs.results["tests"].size(), 17u);
    int renders = 0, unrendered = 0;
    for (const auto& e : fs::recursive_directory_iterator(out / "stubs"))
        renders += e.path().filename() == "worker.json";
    for (const auto& t : stubs.results["tests"]) {
        EXPECT_EQ(t["score"].get<double>(), 0.0) << t["name"];
        const std::string text = t["output"].get<std::string>();
        EXPECT_NE(text.find("not implemented"), std::string::npos) << t;
        unrendered += text.find("(not rendered: it would show the stub too)") != std::string::npos;
    }
    EXPECT_LE(renders, 8) << stubs.run.output;
    EXPECT_EQ(renders + unrendered, 17) << stubs.run.output;

    // moments.glsl solved, the other stages stubs: moments full on every scene, the rest 0.
    const fs::path mixed = out / "mixed";
    fs::copy(test::root() / "student", mixed, fs::copy_options::recursive);
    fs::copy_file(test::root() / "reference" / "moments.glsl", mixed / "moments.glsl",
                  fs::copy_options::overwrite_existing);
    auto g = test::grade("--submission " + mixed.string() + scenes, out / "mixed_out");
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    for (const char* scene : {"classic", "contact", "depth_range", "wide_blur"}) {
        EXPECT_EQ(g.score(scene, "moments"), g.maxScore(scene, "moments")) << scene << "\n" << g.run.output;
        EXPECT_EQ(g.score(scene, "msm"), 0.0) << scene;
        EXPECT_EQ(g.score(scene, "final"), 0.0) << scene;
    }
}

// A fixed-kernel scout speaks only for what its scene runs: on the stubs, every per-pixel SAT
// scene's sat and final tests name satKernelTexels (never probed on contact), and contact's and
// wide_blur's never do, whichever render ran first.
TEST(Grader, PerPixelScenesNameTheKernelStubWhateverTheScout) {
    const fs::path out = test::tempDir("grader_kernel_scout");
    auto g = test::grade("--submission " + (test::root() / "student").string() +
                             " --scenes contact,penumbra,sun_penumbra,wide_blur --reference golden --no-report",
                         out);
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    int checked = 0;
    for (const auto& t : g.results["tests"]) {
        const std::string name = t["name"], text = t["output"];
        const bool sat = name.find(": sat") != std::string::npos, final = name.find(": final") != std::string::npos;
        if (!sat && !final) continue;
        const bool perPixel = name.rfind("penumbra", 0) == 0 || name.rfind("sun_penumbra", 0) == 0;
        EXPECT_EQ(text.find("satKernelTexels") != std::string::npos, perPixel) << name << "\n" << text;
        EXPECT_NE(text.find("satBoxAverage"), std::string::npos) << name << "\n" << text;
        ++checked;
    }
    EXPECT_EQ(checked, 8) << g.run.output;
}

TEST(Grader, ResultsJsonIsWrittenEvenWhenTheGraderCannotRun) {
    fs::path out = test::tempDir("grader_failure");
    auto g = test::grade("--scenes no_such_scene --submission " + (test::root() / "reference").string(), out);
    EXPECT_NE(g.run.exitCode, 0);
    ASSERT_TRUE(g.results.is_object()) << g.run.output;
    EXPECT_EQ(g.results["score"].get<double>(), 0.0);
    EXPECT_NE(g.results["output"].get<std::string>().find("no_such_scene"), std::string::npos);

    std::ofstream(out / "broken.json") << "{ not json";
    auto h = test::grade("--rubric " + (out / "broken.json").string() + " --submission " +
                             (test::root() / "reference").string(), out / "b");
    ASSERT_TRUE(h.results.is_object()) << h.run.output;
    EXPECT_NE(h.results["output"].get<std::string>().find("broken.json"), std::string::npos);
}

TEST(Grader, BatchWritesOneRowPerSubmission) {
    fs::path batch = test::tempDir("grader_batch_in");
    fs::copy(test::root() / "reference", batch / "alice");
    fs::copy(test::root() / "student", batch / "bob");
    fs::path out = test::tempDir("grader_batch_out");
    auto r = test::runCommand(test::shadowlabBinary() + " grade --batch " + batch.string() +
                              " -j 2 --scenes classic --no-report --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("2/2"), std::string::npos) << r.output;  // progress bar
    std::string csv = test::readFile(out / "scores.csv");
    EXPECT_NE(csv.find("student,total,max,moments,gaussian,sat,msm,robustness,final,lost,notes"), std::string::npos) << csv;
    EXPECT_NE(csv.find("alice,100.00,100.00"), std::string::npos) << csv;
    EXPECT_NE(csv.find("bob,0.00,100.00"), std::string::npos) << csv;
    EXPECT_TRUE(fs::exists(out / "alice" / "results.json"));
    EXPECT_TRUE(fs::exists(out / "bob" / "results.json"));
}

TEST(Grader, PackagesLeaveTheSolutionOutOfTheStudentKit) {
    fs::path dir = test::tempDir("grader_package");
    auto r = test::runCommand(test::shadowlabBinary() + " package --kind student --out " +
                              (dir / "kit.tar.gz").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto list = test::runCommand("tar -tzf " + (dir / "kit.tar.gz").string());
    EXPECT_NE(list.output.find("shadowlab/student/msm.glsl"), std::string::npos);
    EXPECT_NE(list.output.find("shadowlab/scenes/goldens/manifest.json"), std::string::npos);
    EXPECT_EQ(list.output.find("shadowlab/reference/"), std::string::npos);
    EXPECT_EQ(list.output.find("tests/submissions"), std::string::npos);
    EXPECT_EQ(list.output.find("shadowlab/build/"), std::string::npos);

    if (test::runCommand("command -v zip && command -v unzip").exitCode != 0)
        GTEST_SKIP() << "zip or unzip is not installed: the Gradescope zip is not checked";
    r = test::runCommand(test::shadowlabBinary() + " package --kind gradescope --out " +
                         (dir / "autograder.zip").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    list = test::runCommand("unzip -l " + (dir / "autograder.zip").string());
    for (const char* f : {" setup.sh", " run_autograder", "source/reference/msm.glsl", "source/grader/rubric.json"})
        EXPECT_NE(list.output.find(f), std::string::npos) << f;
}

}  // namespace sl

namespace sl {

// The SAT precision requirement (docs/numerics.md) in the grader: a plain float32 table
// (tests/submissions/fragile/naive_sat) is a correct algorithm with too little precision: it
// loses all of contact's SAT points (95.7 % of the box means within tolerance, below the sat
// ramp's zero, where every correct variant of the family has >= 99.999 %), keeps wide_blur's
// (a quarter of the stage each, as the handout and docs/numerics.md say), and only the SAT stage
// notices.
TEST(Grader, PlainFloatSatTableLosesPartOfTheSatPointsOnly) {
    const fs::path naive = test::root() / "tests/submissions/fragile/naive_sat";
    fs::path sub = test::makeSubmission(
        "naive_sat", {{"sat.comp", test::readFile(naive / "sat.comp")},
                      {"sat_lookup.glsl", test::readFile(naive / "sat_lookup.glsl")}});
    auto g = test::grade("--submission " + sub.string() + " --scenes contact,wide_blur --no-report",
                         test::tempDir("grader_naive_sat_out"));
    ASSERT_FALSE(g.results.is_null()) << g.run.output;
    const double s = g.score("contact", "sat"), max = g.maxScore("contact", "sat");
    EXPECT_GT(max, 0.0);
    EXPECT_EQ(s, 0.0) << g.output("contact", "sat");
    EXPECT_TRUE(g.full("wide_blur", "sat")) << g.output("wide_blur", "sat");
    for (const char* stage : {"moments", "msm"})
        EXPECT_TRUE(g.full("contact", stage)) << stage << ": " << g.output("contact", stage);
    // The report's finding (where the failing texels lie) is under the score table too.
    EXPECT_NE(g.run.output.find("what the failures look like:\n  - contact (sat, moments_filtered): "),
              std::string::npos) << g.run.output;
    EXPECT_NE(g.run.output.find("away from texel (0, 0)"), std::string::npos) << g.run.output;
}

// The robustness stage (hard cases a fragile MSM must fail): the fragile variants of msm.glsl lose
// points there, with the failing hard cases and their inputs listed; the reference scores full.
TEST(Grader, FragileMsmVariantsLoseRobustnessPointsWithTheCasesListed) {
    const std::vector<std::string> variants = {"mutants/msm_no_moment_bias", "fragile/unguarded"};
    std::map<std::string, fs::path> subs;  // both in one --batch: one reference render
    for (const auto& variant : variants) {
        const fs::path dir = test::root() / "tests/submissions" / variant;
        const std::string tag = dir.filename().string();
        subs[tag] = test::makeSubmission("fragile_" + tag,
                                         {{"msm.glsl", test::readFile(dir / "msm.glsl")}});
    }
    auto graded = test::gradeBatch(subs, "--scenes classic --no-report",
                                   test::tempDir("grader_fragile_out"));
    for (const auto& variant : variants) {
        const test::Graded& g = graded[fs::path(variant).filename().string()];
        ASSERT_FALSE(g.results.is_null()) << g.run.output;
        const std::string out = g.output("hard cases", "robustness");
        EXPECT_LT(g.score("hard cases", "robustness"), g.maxScore("hard cases", "robustness"))
            << variant << ": " << out;
        EXPECT_NE(out.find("b = ("), std::string::npos) << out;  // inputs of a failing case
        EXPECT_TRUE(g.full("classic", "moments")) << variant;
        // The pages quote these counts: each quote is the count this grade measures.
        std::smatch m;
        ASSERT_TRUE(std::regex_search(out, m, std::regex(R"(([0-9]+) failed)"))) << out;
        const std::string failed = m[1];
        const bool bias = variant.find("no_moment_bias") != std::string::npos;
        const std::vector<std::pair<std::string, std::string>> quotes =
            bias ? std::vector<std::pair<std::string, std::string>>{
                       {"docs/grading.md", "Without the moment bias NUM cases are off"},
                       {"docs/numerics.md", "without the moment bias NUM cases are off"},
                       {"docs/numerics.md", "\\| the moment bias \\| NUM failures"},
                       {"docs/catalogue.md", "`msm_no_moment_bias` is off on NUM hard cases"}}
                 : std::vector<std::pair<std::string, std::string>>{
                       {"docs/grading.md", "without the guards NUM cases"},
                       {"docs/numerics.md", "the unguarded solve NUM"},
                       {"docs/numerics.md", "the final clamp \\| NUM failures"}};
        for (const auto& [doc, pattern] : quotes) {
            const std::string text = test::readFile(test::root() / doc);
            const std::string re = std::regex_replace(pattern, std::regex("NUM"), "([0-9]+)");
            std::smatch q;
            ASSERT_TRUE(std::regex_search(text, q, std::regex(re))) << doc << ": no \"" << pattern << "\"";
            EXPECT_EQ(q[1].str(), failed) << doc << " quotes " << q[0] << "; the grade measures " << failed;
        }
    }
}

}  // namespace sl

namespace sl {

// Against the goldens alone (the student kit), msm still gets the reference's filtered moments
// (from a file): a moments bug costs the moments stage, not msm — on a Gaussian and a SAT scene.
TEST(Grader, MsmIsIsolatedAgainstGoldensToo) {
    const fs::path mutant = test::root() / "tests/submissions/mutants/moments_powers_shifted";
    fs::path sub = test::makeSubmission(
        "msm_isolated", {{"moments.glsl", test::readFile(mutant / "moments.glsl")}});
    auto g = test::grade("--reference golden --submission " + sub.string() +
                             " --scenes classic,contact --no-report",
                         test::tempDir("grader_msm_isolated_out"));
    ASSERT_FALSE(g.results.is_null()) << g.run.output;
    for (const char* scene : {"classic", "contact"}) {
        EXPECT_FALSE(g.full(scene, "moments")) << scene;
        EXPECT_TRUE(g.full(scene, "msm")) << scene << ": " << g.output(scene, "msm");
    }
}

// The msm stage's lighting takes each fragment's zf from the reference's relative_depth image,
// never from the submission's relativeDepth: an unclamped relativeDepth (which is wrong exactly
// on depth_range's receivers beyond the far plane) costs msm nothing, live or against the
// goldens alike, and a moments.glsl that does not compile leaves msm full too.
TEST(Grader, MsmNeverRunsTheSubmissionsMomentsGlsl) {
    const fs::path mutant = test::root() / "tests/submissions/mutants/moments_unclamped_relative_depth";
    const fs::path unclamped = test::makeSubmission(
        "msm_zf_unclamped", {{"moments.glsl", test::readFile(mutant / "moments.glsl")}});
    for (const char* mode : {"golden", "live"}) {
        auto g = test::grade(std::string("--reference ") + mode + " --submission " + unclamped.string() +
                                 " --scenes depth_range --no-report",
                             test::tempDir(std::string("grader_msm_zf_") + mode));
        ASSERT_FALSE(g.results.is_null()) << g.run.output;
        EXPECT_FALSE(g.full("depth_range", "moments")) << mode;
        EXPECT_TRUE(g.full("depth_range", "msm")) << mode << ": " << g.output("depth_range", "msm");
    }
    const fs::path broken = test::makeSubmission(
        "msm_zf_broken", {{"moments.glsl", "float relativeDepth(float d, vec2 r) { return d  }\n"}});
    auto g = test::grade("--reference golden --submission " + broken.string() +
                             " --scenes classic --no-report",
                         test::tempDir("grader_msm_zf_broken"));
    ASSERT_FALSE(g.results.is_null()) << g.run.output;
    EXPECT_NE(g.output("classic", "moments").find("compile or link error"), std::string::npos)
        << g.output("classic", "moments");
    EXPECT_TRUE(g.full("classic", "msm")) << g.output("classic", "msm");
}

}  // namespace sl
