// The grader's one stage table and its typed process boundaries: what crosses to a worker, back
// from it, to a batch's child and back, each survives its one encoding; the stage table names
// every stage file; the rubric's defaults are the shipped rubric.json.
#include "batch.h"
#include "exit_codes.h"
#include "rubric.h"
#include "test_grader_support.h"
#include "worker.h"

#include <set>
#include <sstream>

namespace sl {
namespace {

TEST(GraderSeams, TheStageTableNamesEveryStageFileAndKeepsTheReportOrder) {
    std::set<std::string> files;
    for (const auto& row : grader::stageTable()) {
        files.insert(row.files.begin(), row.files.end());
        EXPECT_EQ(&grader::stageRow(row.name), &row) << row.name;
        EXPECT_EQ(&grader::stageRow(row.stage), &row) << row.name;
    }
    const auto& all = stageFileNames();
    EXPECT_EQ(files, std::set<std::string>(all.begin(), all.end()));
    EXPECT_EQ(grader::stageNames(),
              (std::vector<std::string>{"moments", "gaussian", "sat", "msm", "robustness", "final"}));
    EXPECT_THROW(grader::stageRow("gausian"), std::invalid_argument);
    // A final runs moments, its scene's filter and msm; the first missing file is reported, in
    // this order.
    const auto& final = grader::stageRow(grader::Stage::Final);
    EXPECT_EQ(grader::stageFiles(final, "sat"),
              (std::vector<std::string>{"moments.glsl", "msm.glsl", "sat.comp", "sat_lookup.glsl"}));
    EXPECT_EQ(grader::stageFiles(final, "none"), (std::vector<std::string>{"moments.glsl", "msm.glsl"}));
    const auto run = grader::stagesRun(final, "gaussian");
    ASSERT_EQ(run.size(), 3u);
    EXPECT_EQ(run[1]->stage, grader::Stage::Gaussian);
    // msm's stub is seen on the hard cases.
    EXPECT_EQ(grader::stageRow(grader::Stage::Msm).scoutedBy, grader::Stage::Robustness);
}

TEST(GraderSeams, EachStageGradesTheImagesOfItsKindsAndAFilterOnlyTheFirstLightsMap) {
    using grader::gradedImage, grader::stageImage, grader::stageRow, grader::Stage;
    const auto& moments = stageRow(Stage::Moments);
    for (const char* n : {"moments_raw", "moments_raw_light1", "moments_raw_cascade2", "moments_raw_depth_ladder"})
        EXPECT_TRUE(gradedImage(moments, n)) << n;
    for (const char* n : {"moments_filtered", "final", "msm_shadow", "moments_raw_bogus"})
        EXPECT_FALSE(stageImage(moments, n)) << n;
    for (Stage filter : {Stage::Gaussian, Stage::Sat}) {
        const auto& row = stageRow(filter);
        EXPECT_TRUE(gradedImage(row, "moments_filtered"));
        EXPECT_TRUE(gradedImage(row, "moments_filtered_kernel"));
        // The other lights' and cascades' maps are kept (--keep-work) but not graded.
        for (const char* n : {"moments_filtered_light1", "moments_filtered_cascade1", "moments_filtered_layer2"}) {
            EXPECT_TRUE(stageImage(row, n)) << n;
            EXPECT_FALSE(gradedImage(row, n)) << n;
        }
        EXPECT_FALSE(stageImage(row, "sat"));
        EXPECT_FALSE(stageImage(row, "moments_raw"));
    }
    const auto& msm = stageRow(Stage::Msm);
    EXPECT_TRUE(gradedImage(msm, "shadow"));
    EXPECT_TRUE(gradedImage(msm, "shadow_overhead"));
    EXPECT_FALSE(gradedImage(msm, "msm_shadow"));  // the reference's lighting-only render
    EXPECT_FALSE(gradedImage(msm, "final"));
    EXPECT_TRUE(gradedImage(stageRow(Stage::Final), "final_overhead"));
    EXPECT_FALSE(gradedImage(stageRow(Stage::Final), "shadow"));
}

TEST(GraderSeams, WorkerArgumentsAndResultsCrossInOneEncoding) {
    grader::WorkerArgs a;
    a.scene = "/k/scenes/classic.json";
    a.stage = &grader::stageRow(grader::Stage::Sat);
    a.submission = "/o/.work-1/submission";
    a.input = "/o/ref/classic/moments_raw.raw";
    a.out = "/o/classic/sat";
    a.backend = "egl";
    const auto b = grader::WorkerArgs::fromJson(nlohmann::json::parse(a.toJson().dump()));
    EXPECT_EQ(b.toJson(), a.toJson());
    EXPECT_EQ(b.stage, a.stage);
    a.stage = nullptr;  // the reference render
    EXPECT_EQ(grader::WorkerArgs::fromJson(a.toJson()).stage, nullptr);
    nlohmann::json broken = a.toJson();
    broken.erase("out");
    try {
        grader::WorkerArgs::fromJson(broken);
        ADD_FAILURE() << "a missing field was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("out"), std::string::npos) << e.what();
    }

    grader::WorkerResult r;
    r.stage = "final";
    r.stubEverywhere = true;
    r.images = {"final", "final_1"};
    r.stubNotes = {{"sat_lookup.glsl", "submission/sat_lookup.glsl: satBoxAverage: not implemented yet"},
                   {"", "shaders/x.glsl: y: not implemented yet"}};
    r.mesaVersion = "22.3.6";
    const auto back = grader::WorkerResult::fromJson(nlohmann::json::parse(r.toJson().dump()));
    EXPECT_EQ(back.toJson(), r.toJson());
    ASSERT_EQ(back.stubNotes.size(), 2u);
    EXPECT_EQ(back.stubNotes[0].file, "sat_lookup.glsl");
    EXPECT_EQ(back.stubNotes[1].file, "");
}

TEST(GraderSeams, GradeOptionsAndBatchRowsCrossInOneEncoding) {
    grader::GradeOptions o;
    o.submission = "/b/alice";
    o.out = "/o/alice";
    o.scenes = {"public", "/h/shelf.json"};
    o.timeoutSeconds = 7.5;
    o.memoryMb = 2048;
    o.report = false;
    o.keepWork = true;
    o.rowFile = "/o/.rows/alice.json";
    const auto p = grader::GradeOptions::fromJson(nlohmann::json::parse(o.toJson().dump()));
    EXPECT_EQ(p.toJson(), o.toJson());
    EXPECT_EQ(p.scenes, o.scenes);
    EXPECT_EQ(p.memoryMb, 2048);

    grader::GradeSummary s;
    grader::TestResult t;
    t.scene = "classic", t.stage = "msm", t.score = 6.666, t.maxScore = 6.67;
    s.tests = {t};
    s.score = t.score;
    s.warnings = {"ignored (not stage files): notes.txt", "reference render of x failed: a\nb"};
    const grader::BatchRow row = grader::batchRow(s);
    EXPECT_FALSE(row.failed);
    EXPECT_DOUBLE_EQ(row.stagePoints.at("msm"), 6.67);
    // One line a note, as results.json's warning lines.
    EXPECT_EQ(row.notes, (std::vector<std::string>{"ignored (not stage files): notes.txt",
                                                   "reference render of x failed: a"}));
    EXPECT_EQ(grader::BatchRow::fromJson(row.toJson()).toJson(), row.toJson());
    grader::GradeSummary failed;
    failed.failed = true;
    failed.failure = "unknown scene \"x\"\nmore";
    EXPECT_EQ(grader::batchRow(failed).notes,
              std::vector<std::string>{"The grader could not grade this submission: unknown scene \"x\""});
}

TEST(GraderSeams, ErrorsMapToExitCodesInOnePlace) {
    std::ostringstream err;
    EXPECT_EQ(reportError(std::make_exception_ptr(SceneError("s.json: /lights: bad")), err), BadInput);
    EXPECT_EQ(reportError(std::make_exception_ptr(std::runtime_error("disk full")), err), Failed);
    EXPECT_EQ(err.str(), "scene error: s.json: /lights: bad\nerror: disk full\n");
}

TEST(GraderSeams, TheDefaultRubricIsTheShippedFileAndAStageWithoutItsOwnRampFollowsTheGlobalOne) {
    const grader::Rubric d = grader::defaultRubric();
    const grader::Rubric shipped = grader::loadRubric(test::root() / "grader" / "rubric.json");
    for (const auto& st : grader::stageNames()) {
        EXPECT_EQ(d.ramp(st), shipped.ramp(st)) << st;
        EXPECT_EQ(d.weights.at(st), shipped.weights.at(st)) << st;
    }
    EXPECT_EQ(d.total, 100.0);
    // A course rubric that moves the global ramp moves every stage that has none of its own.
    const fs::path dir = test::tempDir("grader_seams_rubric");
    std::ofstream(dir / "r.json") << R"({"pass_fraction": 0.99, "zero_fraction": 0.5})";
    const grader::Rubric r = grader::loadRubric(dir / "r.json");
    EXPECT_EQ(r.ramp("moments"), (std::pair<double, double>{0.99, 0.5}));
    EXPECT_EQ(r.ramp("msm"), d.ramp("msm"));
}

}  // namespace
}  // namespace sl
