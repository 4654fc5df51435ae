// grade: one submission, end to end. Intake, then the reference renders (or the goldens),
// then one child process per (scene, stage), two at a time, then the comparisons, the
// results.json and the report. Whatever happens, results.json is written.
#include "gl_context.h"
#include "golden.h"
#include "grader.h"
#include "image_codec.h"
#include "intake.h"
#include "isolation.h"
#include "jobs.h"
#include "paths.h"
#include "points.h"
#include "phase_clock.h"
#include "report.h"
#include "results.h"
#include "rubric.h"
#include "scene_list.h"
#include "score_render.h"
#include "shader_source.h"
#include "stub_scouts.h"
#include "worker.h"

#include "image_io.h"
#include "raw_image.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>

namespace sl::grader {
namespace {

struct Job {
    size_t scene;
    const StageRow* row;  // nullptr: the reference render
    fs::path out;
    std::string missing;  // "file: reason" when a file it needs was not taken
    ChildResult child;
    bool ran = false;
    bool dropped = false;  // "either" mode: a final of the filter not kept (not rendered, no test)
    std::string notRunReason;  // not rendered: another scene's render showed the stage a stub
    bool reference() const { return row == nullptr; }
    bool is(Stage stage) const { return row && row->stage == stage; }
};

// The renders of one grade in the order they start: the reference renders (their times set
// the others' limits), the stage renders, and in "either" mode the finals of the filter scenes
// (they wait for the filter stages' scores).
struct Schedule {
    std::vector<size_t> references, stages, finals;
};


std::string jobName(const Job& j) { return j.row ? j.row->name : "reference"; }

Job makeJob(size_t scene, const StageRow* row, const fs::path& out) {
    Job j;
    j.scene = scene;
    j.row = row;
    j.out = out;
    return j;
}

class Grading {
public:
    Grading(const GradeOptions& o, const Rubric& r) : o_(o), rubric_(r) {}

    GradeSummary run() {
        PhaseClock clock("grade");
        clock.lap("start");
        GradeSummary s;
        takeSubmission(s);
        checkGoldens(s);
        const Schedule schedule = planJobs();
        clock.lap("intake and plan");
        renderReferences(schedule.references);
        clock.lap("reference renders");
        renderStages(schedule);
        clock.lap("stage renders (waiting for workers) and scores");
        renderWarnings(s);
        total(s);
        clock.lap("comparisons and report");
        std::error_code ec;
        if (!o_.keepWork) fs::remove_all(workDir(o_), ec);
        return s;
    }

private:
    // The submission's files copied into the work folder, the scenes and the reference mode.
    void takeSubmission(GradeSummary& s) {
        const fs::path work = workDir(o_);
        std::error_code ec;
        fs::remove_all(work, ec);
        fs::create_directories(work);
        intake_ = grader::takeSubmission(o_.submission, work / "submission");
        scenes_ = gradedScenes(o_.scenes);
        haveRef_ = haveReference();
        mode_ = resolveReferenceMode(o_.reference);
        s.referenceMode = mode_;
        if (mode_ == "live" && !haveRef_)
            throw std::runtime_error("--reference live needs reference/; use --reference golden");
        goldens_ = o_.goldens.empty() ? repoRoot() / "scenes" / "goldens" : o_.goldens;
        if (!intake_.ignored.empty()) {
            std::string names;
            for (const auto& n : intake_.ignored) names += " " + n;
            ignoredWarning_ = "ignored (not stage files):" + names;
        }
    }

    // Golden mode: every scene has goldens, made from the scene file as it is now.
    void checkGoldens(GradeSummary& s) {
        if (mode_ == "golden") {
            for (const auto& scene : scenes_) {
                // A hidden scene's goldens are in goldens/ next to its file (golden.h).
                const nlohmann::json manifest = readManifest(goldenFolder(scene, goldens_));
                if (manifest.is_null())
                    throw std::runtime_error(
                        scene.hidden ? "no golden images for a hidden scene (make them with: "
                                       "shadowlab golden --scenes <its file>)"
                                     : "no golden images in " + goldens_.string() +
                                           " (make them with: shadowlab golden --solution reference)");
                const auto& entry = manifest["scenes"].contains(scene.name)
                                        ? manifest["scenes"][scene.name] : nlohmann::json();
                if (entry.is_null())
                    s.warnings.push_back("no goldens for scene " + scene.name);
                else if (entry.value("scene_sha256", "") != sha256File(scene.path))
                    s.warnings.push_back("scene " + scene.name + " changed since its goldens were made");
            }
        }
        if (!ignoredWarning_.empty()) s.warnings.push_back(ignoredWarning_);
    }

    // One job per render, in scoring order (that of the report's findings): the stage renders
    // without reference input, the robustness test, then the stages that read a reference
    // image; and the order they start in.
    Schedule planJobs() {
        std::vector<Job> own, needInput;
        for (size_t i = 0; i < scenes_.size(); ++i) {
            if (mode_ == "live" && o_.referenceImages.empty())
                own.push_back(makeJob(i, nullptr, workDir(o_) / "ref" / scenes_[i].name));
            for (const StageRow& row : stageTable()) {
                if (!row.perScene || (*row.filter && row.filter != scenes_[i].filter)) continue;
                Job job = makeJob(i, &row, workDir(o_) / scenes_[i].name / row.name);
                job.missing = firstMissing(stageFiles(row, scenes_[i].filter));
                (*row.input ? needInput : own).push_back(job);
            }
        }
        // The robustness stage: one test, the submission's msm.glsl on the hard cases.
        if (!scenes_.empty()) {
            const StageRow& row = stageRow(Stage::Robustness);
            Job job = makeJob(0, &row, workDir(o_) / row.name);
            job.missing = firstMissing(row.files);
            own.push_back(job);
        }
        jobs_ = std::move(own);
        jobs_.insert(jobs_.end(), needInput.begin(), needInput.end());
        Schedule order;
        for (size_t k = 0; k < jobs_.size(); ++k) {
            if (jobs_[k].reference()) order.references.push_back(k);
            // "either": the final renders of a filter's scenes wait for the filter stages, and
            // only the kept filter's are rendered (assignPoints drops the others' tests).
            else if (rubric_.filters == "either" && jobs_[k].is(Stage::Final) &&
                     scenes_[jobs_[k].scene].filter != "none")
                order.finals.push_back(k);
            else order.stages.push_back(k);
        }
        order.stages = scoutsFirst(order.stages);
        return order;
    }

    // "file: reason" for the first of `files` the intake did not take, "" if it took them all.
    std::string firstMissing(const std::vector<std::string>& files) const {
        for (const auto& f : files)
            if (!intake_.has(f)) return f + ": " + intake_.refused.at(f);
        return "";
    }

    // The reference renders (live), or the goldens decoded; then the scenes' probes must hold
    // on the reference they are graded against, or grading stops.
    void renderReferences(const std::vector<size_t>& references) {
        const auto times = readReferenceTimes(o_.referenceImages);
        for (size_t i = 0; i < scenes_.size(); ++i)
            if (times.count(scenes_[i].name)) refSeconds_[i] = times.at(scenes_[i].name);
        if (mode_ == "golden") decodeGoldens(o_, scenes_, goldens_);
        runPhase(references);
        checkReferenceProbes(scenes_, [this](size_t i, const std::string& image) {
            return referenceFile(i, image);
        });
    }

    // Every stage render in one run: a barrier between the stages without and with reference
    // input left a core idle at its end, and cost a submission that loops in every stage one
    // more whole time limit. Each test is scored as soon as it and those before it in jobs_
    // are done, while the next renders run.
    void renderStages(const Schedule& schedule) {
        if (o_.report) report_ = std::make_unique<ReportWriter>(o_.out / "report");
        runPhase(schedule.stages);
        if (!schedule.finals.empty()) {
            std::vector<TestResult> filterTests;
            for (size_t k : schedule.stages)
                if (*jobs_[k].row->filter) filterTests.push_back(score(jobs_[k], nullptr));
            const std::string kept = betterFilter(filterTests);
            std::vector<size_t> run;
            for (size_t k : schedule.finals) {
                jobs_[k].dropped = !kept.empty() && scenes_[jobs_[k].scene].filter != kept;
                if (!jobs_[k].dropped) run.push_back(k);
            }
            scoreReady();
            runPhase(run);
        }
        scoreReady();
    }

    // The renderer the workers ran against the goldens' (golden mode), or the reference
    // renders that failed (live).
    void renderWarnings(GradeSummary& s) const {
        if (mode_ == "golden") {
            for (const auto& w : manifestWarnings(readManifest(goldens_), running_))
                s.warnings.push_back(w);
            return;
        }
        for (const auto& j : jobs_)
            if (j.reference() && !(j.child.kind == ChildResult::Exited && j.child.exitCode == 0))
                s.warnings.push_back("reference render of " + scenes_[j.scene].name +
                                     " failed: " + failureText(j.child, o_));
    }

    // The tests in report order, their points in exact hundredths under the rubric's filter
    // mode (points.h), what the failures look like, and the report's page.
    void total(GradeSummary& s) {
        s.tests = std::move(tests_);
        std::sort(s.tests.begin(), s.tests.end(), [](const TestResult& a, const TestResult& b) {
            auto rank = [](const std::string& st) {
                const auto& n = stageNames();
                return std::find(n.begin(), n.end(), st) - n.begin();
            };
            return a.scene != b.scene ? a.scene < b.scene : rank(a.stage) < rank(b.stage);
        });
        assignPoints(s, rubric_);
        s.findings = diagnose(s, imageFindings_, false);
        if (report_) report_->finish(s);
    }

    // The scouts (stub_scouts.h) first, the robustness test (short) before the others.
    std::vector<size_t> scoutsFirst(const std::vector<size_t>& order) {
        std::vector<size_t> first, rest;
        for (size_t k : order) {
            const Job& j = jobs_[k];
            const bool scout = j.missing.empty() && j.row->scoutedBy == j.row->stage &&
                               scouts_.emplace(j.row->stage, k).second;
            (scout ? first : rest).push_back(k);
        }
        std::stable_partition(first.begin(), first.end(),
                              [this](size_t k) { return jobs_[k].is(Stage::Robustness); });  // short
        first.insert(first.end(), rest.begin(), rest.end());
        return first;
    }

    // The note of a finished scout whose stage is the stub everywhere: its own stub note
    // (computeMoments, momentShadowIntensity) or, for a filter, the stage's files. "" if it is
    // not a stub, failed or was not run; nullopt while it runs (worker.json is written last).
    std::optional<std::string> scoutNote(size_t scout) {
        if (auto known = scoutNote_.find(scout); known != scoutNote_.end()) return known->second;
        const Job& j = jobs_[scout];
        const auto w = readWorkerResult(j.out);
        if (!w) {
            std::error_code ec;
            if (!fs::exists(j.out / kWorkerResultFile, ec))
                return j.ran ? std::optional<std::string>("") : std::nullopt;
            return std::nullopt;  // still being written: ask again at the next start
        }
        return scoutNote_[scout] = scoutStubNote(*j.row, j.is(Stage::Robustness), *w);
    }

    // skipIf of job k: true (with the reason in notRunReason) if a scout showed a stage it
    // renders from the submission to be the stub.
    bool stubbedElsewhere(size_t k) {
        Job& job = jobs_[k];
        std::string reason;
        for (const StageRow* run : stagesRun(*job.row, scenes_[job.scene].filter)) {
            if (!run->scoutedBy) continue;
            const auto scout = scouts_.find(*run->scoutedBy);
            if (scout == scouts_.end() || scout->second == k) continue;
            const Job& seenBy = jobs_[scout->second];
            if (!scoutSpeaksFor(run->stage, perPixelSat(seenBy.scene), perPixelSat(job.scene))) return false;
            const auto note = scoutNote(scout->second);
            if (!note || note->empty()) continue;
            reason += spareReason(*note, run->stage, perPixelSat(job.scene), seenBy.is(Stage::Robustness),
                                  scenes_[seenBy.scene]);
        }
        if (reason.empty()) return false;
        job.notRunReason = reason + "(not rendered: it would show the stub too)\n";
        return true;
    }

    bool perPixelSat(size_t scene) const {
        const auto& s = scenes_[scene].scene;
        return s && s->shadow.filter == FilterKind::Sat && s->shadow.satPerPixel;
    }

    std::map<Stage, size_t> scouts_;            // stage -> the job that speaks for it
    std::map<size_t, std::string> scoutNote_;   // finished scout -> its stub note, "" if none
    const bool timing_ = std::getenv("SHADOWLAB_GRADER_TIMING") != nullptr;  // per-job times too

    // Files a stage's render compiles from the submission.
    fs::path referenceFile(size_t scene, const std::string& image) const {
        const fs::path refs = o_.referenceImages.empty() ? workDir(o_) / "ref" : o_.referenceImages;
        if (mode_ == "live") return refs / scenes_[scene].name / (image + ".raw");
        const fs::path decoded = workDir(o_) / "golden" / scenes_[scene].name / (image + ".raw");
        std::error_code ec;
        if (fs::exists(decoded, ec)) return decoded;
        return goldenFolder(scenes_[scene], goldens_) / scenes_[scene].name / (image + ".exr");
    }

    // Runs the jobs at `which` (indices into jobs_), two at a time; scores as they end.
    void runPhase(const std::vector<size_t>& which) {
        std::vector<ChildSpec> specs;
        std::vector<size_t> index;
        for (size_t k : which) {
            Job& j = jobs_[k];
            if (!j.missing.empty()) continue;
            fs::create_directories(j.out);
            // The reference moments a stage reads; a render of the scene alone is handed
            // moments_raw, which it does not read (the worker's arguments as they always were).
            const char* input = j.row && *j.row->input ? j.row->input : "moments_raw";
            specs.push_back(workerSpec(o_, scenes_[j.scene], j.row,
                                       referenceFile(j.scene, input), j.out));
            const double ref = refSeconds_.count(j.scene) ? refSeconds_.at(j.scene) : 0.0;
            specs.back().timeoutSeconds = j.reference() ? referenceTimeout(o_) : stageTimeout(o_, ref);
            specs.back().limitNote = j.reference() ? "" : timeoutNote(o_, ref);
            if (!j.reference()) specs.back().skipIf = [this, k] { return stubbedElsewhere(k); };
            // Once a stage whose files a final runs has timed out (it loops), the finals not
            // started yet would wait out their limits too.
            if (j.is(Stage::Final))
                for (const StageRow* run : stagesRun(*j.row, scenes_[j.scene].filter))
                    specs.back().alsoRuns.push_back(run->name);
            index.push_back(k);
        }
        // A scoring error fails the grade (results.json says why), once every child has ended.
        std::exception_ptr failed;
        auto results = runChildren(specs, {kTimeoutDefault, o_.memoryMb, true}, o_.jobs,
                                   [&](size_t i, const ChildResult& r) {
                                       Job& j = jobs_[index[i]];
                                       j.child = r;
                                       j.ran = true;
                                       if (timing_)
                                           std::cerr << "grade: " << jobName(j) << " "
                                                     << testScene(j.row, scenes_[j.scene]) << ": "
                                                     << (r.notRun ? "not run (a stub)" : std::to_string(r.seconds) + " s")
                                                     << "\n";
                                       if (j.reference() || failed) return;
                                       try {
                                           scoreReady();
                                       } catch (...) {
                                           failed = std::current_exception();
                                       }
                                   },
                                   &timedOut_);
        if (failed) std::rethrow_exception(failed);
        for (size_t k = 0; k < results.size(); ++k) {
            Job& j = jobs_[index[k]];
            if (j.reference()) refSeconds_[j.scene] = j.child.seconds;
            if (running_.is_null() && j.child.kind == ChildResult::Exited && j.child.exitCode == 0)
                if (const auto w = readWorkerResult(j.out)) running_ = w->toJson();
        }
    }

    // Scores the tests of jobs_ in order, as far as their renders are done (a job with a
    // missing file has nothing to render; a dropped one has no test).
    void scoreReady() {
        for (; scored_ < jobs_.size(); ++scored_) {
            const Job& j = jobs_[scored_];
            if (j.reference() || j.dropped) continue;
            if (!j.ran && j.missing.empty()) return;
            // A skipped stub's test names every stub its files hold: once every scout is done.
            if (j.child.notRun && !std::all_of(scouts_.begin(), scouts_.end(),
                                               [&](const auto& s) { return jobs_[s.second].ran; }))
                return;
            tests_.push_back(score(j, report_.get()));
        }
    }

    // The test of a finished render (score_render.h); `fraction` holds its share of the
    // points (assignPoints scales it).
    TestResult score(const Job& job, ReportWriter* report) {
        // A stub seen by a scout that finished after this job was skipped: named too (every
        // scout is done by now, scoreReady).
        if (job.child.notRun) stubbedElsewhere(size_t(&job - jobs_.data()));
        const RenderToScore render{*job.row, scenes_[job.scene], job.out, job.missing, job.child,
                                   job.notRunReason};
        return scoreRender(render, o_, rubric_,
                           [&](const std::string& image) { return referenceFile(job.scene, image); }, report,
                           &imageFindings_);
    }

    const GradeOptions& o_;
    const Rubric& rubric_;
    IntakeResult intake_;
    std::vector<GradedScene> scenes_;
    bool haveRef_ = false;
    std::string mode_;
    fs::path goldens_;
    std::string ignoredWarning_;  // the submission's other files, named
    nlohmann::json running_;  // backend/renderer/Mesa of the workers
    std::map<size_t, double> refSeconds_;  // scene -> its reference render's seconds
    TimedOutGroups timedOut_;  // stage -> its first timeout, over every phase of stage renders
    std::vector<Job> jobs_;                // every render, in scoring order
    size_t scored_ = 0;                    // jobs_[0, scored_) are scored
    std::vector<TestResult> tests_;
    std::unique_ptr<ReportWriter> report_;
    std::vector<ImageFindings> imageFindings_;  // where each compared image fails (the findings)
};

}  // namespace

GradeSummary gradeSubmission(const GradeOptions& o) {
    const auto start = std::chrono::steady_clock::now();
    auto seconds = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    GradeSummary s;
    const fs::path results = o.out / "results.json";
    try {
        std::error_code ec;
        fs::create_directories(o.out, ec);
        Rubric rubric = loadRubric(o.rubric.empty() ? repoRoot() / "grader" / "rubric.json" : o.rubric);
        // Once here, not in every forked child: the driver, and the image codec that the
        // goldens' decoders and this process's comparisons and report need (loaded through
        // loadBeforeForking: log4cplus starts idle threads).
        preloadDriver(parseBackendKind(o.backend));
        loadBeforeForking([] { imageCodec(); });
        s = Grading(o, rubric).run();
        s.seconds = seconds();
        writeResults(results, resultsJson(s, rubric));
    } catch (const std::exception& e) {
        s = {};
        s.failed = true;
        s.failure = e.what();
        s.warnings.push_back(std::string("grader failed: ") + e.what());
        s.seconds = seconds();
        writeFailureResults(results, e.what(), s.seconds);
    } catch (...) {
        s = {};
        s.failed = true;
        s.failure = "unknown error";
        s.warnings.push_back("grader failed: unknown error");
        writeFailureResults(results, "unknown error", seconds());
    }
    return s;
}

}  // namespace sl::grader
