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
#include "metrics.h"
#include "paths.h"
#include "points.h"
#include "depth_ladder.h"
#include "report.h"
#include "results.h"
#include "rubric.h"
#include "scene_list.h"
#include "scene.h"
#include "shader_source.h"

#include "image_io.h"
#include "raw_image.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace sl::grader {
namespace {

struct Job {
    size_t scene;
    std::string stage;
    fs::path out;
    std::string missing;  // "file: reason" when a file it needs was not taken
    ChildResult child;
    bool ran = false;
    bool dropped = false;  // "either" mode: a final of the filter not kept (not rendered, no test)
    std::string notRunReason;  // not rendered: another scene's render showed the stage a stub
};

// Phase times on stderr with SHADOWLAB_GRADER_TIMING=1 (docs/performance.md).
struct Stopwatch {
    std::chrono::steady_clock::time_point last = std::chrono::steady_clock::now();
    bool on = std::getenv("SHADOWLAB_GRADER_TIMING") != nullptr;
    void lap(const char* what) {
        const auto now = std::chrono::steady_clock::now();
        if (on) std::cerr << "grade: " << what << ": " << std::chrono::duration<double>(now - last).count() << " s\n";
        last = now;
    }
};

Job makeJob(size_t scene, const std::string& stage, const fs::path& out) {
    Job j;
    j.scene = scene;
    j.stage = stage;
    j.out = out;
    return j;
}

std::string fmt(double v, int digits = 2) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(digits);
    s << v;
    return s.str();
}

// What the child's failure means for the student.
std::string failureText(const ChildResult& c, const GradeOptions& o) {
    switch (c.kind) {
        case ChildResult::TimedOut:
            return "timed out after " + fmt(c.limitSeconds, 0) + " s" + c.limitNote +
                   ": the render was stopped (look for a loop that never ends)" +
                   (!c.skipped ? ""
                    : c.skippedAfter.empty() ? "; not run here: this stage timed out on another scene"
                    : "; not run here: the " + c.skippedAfter +
                          " stage timed out, and this render runs its files too");
        case ChildResult::Signalled: return "crashed: " + signalName(c.signal);
        case ChildResult::StartFailed: return "the grader could not start its worker";
        case ChildResult::Exited: break;
    }
    std::string log = c.log;
    if (c.exitCode == 3) {  // ShaderError: file:line lines, then the driver's log
        const std::string head = "shader error:\n";
        if (auto p = log.find(head); p != std::string::npos) log = log.substr(p + head.size());
        if (log.size() > 4000) log = log.substr(0, 4000) + "\n...";
        return "compile or link error:\n" + log;
    }
    if (log.size() > 2000) log = "..." + log.substr(log.size() - 2000);
    std::string text = "render failed (exit " + std::to_string(c.exitCode) + "): " + log;
    if (log.find("alloc") != std::string::npos || log.find("memory") != std::string::npos ||
        log.find("map") != std::string::npos)
        text += "\n(the memory limit is " + std::to_string(o.memoryMb) + " MB)";
    return text;
}

// Where the worst texel is and what it holds, so that a student can reproduce it (probe).
std::string worstTexelText(const std::string& image, const Comparison& c) {
    std::ostringstream o;
    o.precision(7);
    if (image == kDepthLadderImage) {
        const glm::vec3 in = relativeDepthLadder().at(size_t(c.worstX));
        o << "  worst: ladder row " << c.worstX << " (lightDepth " << in.x << ", near " << in.y
          << ", far " << in.z << "): b" << c.worstChannel + 1 << " = " << c.worstValue
          << ", expected " << c.worstExpected
          << " (shadowlab probe moments --generate depth-ladder writes these rows)";
        return o.str();
    }
    o << "  worst texel: x " << c.worstX << ", y " << c.worstY
      << " (from the bottom-left; its centre is (" << c.worstX + 0.5 << ", " << c.worstY + 0.5
      << ")), channel b" << c.worstChannel + 1 << ": " << c.worstValue << ", expected "
      << c.worstExpected << " (" << fmt(std::min(c.worst, 1e6), 1) << "x the tolerance)";
    return o.str();
}

class Grading {
public:
    Grading(const GradeOptions& o, const Rubric& r) : o_(o), rubric_(r) {}

    GradeSummary run() {
        GradeSummary s;
        const fs::path work = workDir(o_);
        std::error_code ec;
        fs::remove_all(work, ec);
        fs::create_directories(work);
        intake_ = takeSubmission(o_.submission, work / "submission");
        scenes_ = uniqueScenes(gradedScenes(o_.scenes));
        haveRef_ = haveReference();
        mode_ = resolveReferenceMode(o_.reference);
        s.referenceMode = mode_;
        if (mode_ == "live" && !haveRef_)
            throw std::runtime_error("--reference live needs reference/; use --reference golden");
        goldens_ = o_.goldens.empty() ? repoRoot() / "scenes" / "goldens" : o_.goldens;
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
        if (!intake_.ignored.empty()) {
            std::string names;
            for (const auto& n : intake_.ignored) names += " " + n;
            s.warnings.push_back("ignored (not stage files):" + names);
        }

        // Phase A: reference renders and the stages that need no reference input file; phase
        // B: the stages that read a reference image (run after the reference renders).
        std::vector<Job> phaseA, phaseB;
        for (size_t i = 0; i < scenes_.size(); ++i) {
            if (mode_ == "live" && o_.referenceImages.empty()) phaseA.push_back(makeJob(i, "reference", work / "ref" / scenes_[i].name));
            for (const auto& stage : stageNames()) {
                if (!stageApplies(stage, scenes_[i].filter)) continue;
                Job job = makeJob(i, stage, work / scenes_[i].name / stage);
                for (const auto& f : neededFiles(stage, scenes_[i].filter))
                    if (!intake_.has(f) && job.missing.empty())
                        job.missing = f + ": " + intake_.refused.at(f);
                // These read a reference image as input: after the reference renders.
                const bool needsInput = stage == "gaussian" || stage == "sat" || stage == "msm";
                (needsInput ? phaseB : phaseA).push_back(job);
            }
        }
        // The robustness stage: one test, the submission's msm.glsl on the hard cases.
        if (!scenes_.empty()) {
            Job job = makeJob(0, "robustness", work / "robustness");
            if (!intake_.has("msm.glsl")) job.missing = "msm.glsl: " + intake_.refused.at("msm.glsl");
            phaseA.push_back(job);
        }
        Stopwatch clock;
        // One list in scoring order (that of the report's findings): the stage renders without
        // reference input, the robustness test, then the stages that read a reference image.
        jobs_ = std::move(phaseA);
        jobs_.insert(jobs_.end(), phaseB.begin(), phaseB.end());
        // The reference renders first: their times set the other renders' limits (jobs.h).
        std::vector<size_t> refJobs, stageJobs, finals;
        for (size_t k = 0; k < jobs_.size(); ++k) {
            if (jobs_[k].stage == "reference") refJobs.push_back(k);
            // "either": the final renders of a filter's scenes wait for the filter stages, and
            // only the kept filter's are rendered (assignPoints drops the others' tests).
            else if (rubric_.filters == "either" && jobs_[k].stage == "final" &&
                     scenes_[jobs_[k].scene].filter != "none")
                finals.push_back(k);
            else stageJobs.push_back(k);
        }
        stageJobs = scoutsFirst(stageJobs);
        const auto times = readReferenceTimes(o_.referenceImages);
        for (size_t i = 0; i < scenes_.size(); ++i)
            if (times.count(scenes_[i].name)) refSeconds_[i] = times.at(scenes_[i].name);
        if (mode_ == "golden") decodeGoldens();
        runPhase(refJobs);
        clock.lap("reference renders");
        // The scenes' probes hold on the reference they are graded against, or grading stops.
        checkReferenceProbes(scenes_, [this](size_t i, const std::string& image) {
            return referenceFile(i, image);
        });
        if (o_.report) report_ = std::make_unique<ReportWriter>(o_.out / "report");
        // Every stage render in one run: a barrier between the stages without and with
        // reference input left a core idle at its end, and cost a submission that loops in
        // every stage one more whole time limit. Each test is scored as soon as it and those
        // before it in jobs_ are done, while the next renders run.
        runPhase(stageJobs);
        if (!finals.empty()) {
            std::vector<TestResult> filterTests;
            for (size_t k : stageJobs)
                if (jobs_[k].stage == "gaussian" || jobs_[k].stage == "sat")
                    filterTests.push_back(score(jobs_[k], nullptr));
            const std::string kept = betterFilter(filterTests);
            std::vector<size_t> run;
            for (size_t k : finals) {
                jobs_[k].dropped = !kept.empty() && scenes_[jobs_[k].scene].filter != kept;
                if (!jobs_[k].dropped) run.push_back(k);
            }
            scoreReady();
            runPhase(run);
        }
        scoreReady();
        clock.lap("stage renders (and scores)");
        if (mode_ == "golden") {
            for (const auto& w : manifestWarnings(readManifest(goldens_), running_))
                s.warnings.push_back(w);
        } else {
            for (auto& j : jobs_)
                if (j.stage == "reference" && !(j.child.kind == ChildResult::Exited &&
                                                j.child.exitCode == 0))
                    s.warnings.push_back("reference render of " + scenes_[j.scene].name +
                                         " failed: " + failureText(j.child, o_));
        }
        s.tests = std::move(tests_);
        std::sort(s.tests.begin(), s.tests.end(), [](const TestResult& a, const TestResult& b) {
            auto rank = [](const std::string& st) {
                const auto& n = stageNames();
                return std::find(n.begin(), n.end(), st) - n.begin();
            };
            return a.scene != b.scene ? a.scene < b.scene : rank(a.stage) < rank(b.stage);
        });
        // Points in exact hundredths; the rubric's filter mode (points.h).
        assignPoints(s, rubric_);
        if (report_) report_->finish(s);
        clock.lap("comparisons and report");
        if (!o_.keepWork) fs::remove_all(work, ec);
        return s;
    }

private:
    // Scouts: a stub stage's output is -1 on every scene, so once one render of a stage shows
    // the stub everywhere, its renders of the other scenes, and the finals that use it, are not
    // run: they would score 0 as "not implemented" all the same. A student's first `./kit check`
    // on the stubs renders 5 of 25 tests. The scouts run first: the robustness test speaks for
    // msm.glsl (-1 on every hard case), the first moments, gaussian and sat renders for their
    // stages (stubEverywhere in worker.json: computeMoments -1 on every rung of the depth
    // ladder, a filter's whole output -1). Any other outcome of a scout renders everything.
    std::vector<size_t> scoutsFirst(const std::vector<size_t>& order) {
        std::vector<size_t> first, rest;
        for (size_t k : order) {
            const Job& j = jobs_[k];
            const std::string stage = j.stage == "robustness" ? "msm" : j.stage;
            const bool scout = j.missing.empty() && stage != "final" && (stage != "msm" || j.stage == "robustness") &&
                               scouts_.emplace(stage, k).second;
            (scout ? first : rest).push_back(k);
        }
        std::stable_partition(first.begin(), first.end(),
                              [this](size_t k) { return jobs_[k].stage == "robustness"; });  // short
        first.insert(first.end(), rest.begin(), rest.end());
        return first;
    }

    // The note of a finished scout whose stage is the stub everywhere: its own stub note
    // (computeMoments, momentShadowIntensity) or, for a filter, the stage's files. "" if it is
    // not a stub, failed or was not run; nullopt while it runs (worker.json is written last).
    std::optional<std::string> scoutNote(size_t scout) {
        if (auto known = scoutNote_.find(scout); known != scoutNote_.end()) return known->second;
        nlohmann::json w;
        try {
            std::ifstream in(jobs_[scout].out / "worker.json");
            if (!in) return jobs_[scout].ran ? std::optional<std::string>("") : std::nullopt;
            w = nlohmann::json::parse(in);
        } catch (const std::exception&) {
            return std::nullopt;  // still being written: ask again at the next start
        }
        const Job& j = jobs_[scout];
        const auto notes = w.value("stubNotes", std::vector<std::string>{});
        std::string note;
        if (j.stage == "robustness" ? !notes.empty() : w.value("stubEverywhere", false)) {
            for (const auto& f : stageFiles(j.stage, ""))
                note += (note.empty() ? "submission/" : " + ") + f;
            note += ": not implemented yet (its output is the stub value -1)";
            for (const auto& n : notes)
                if (n.find("submission/" + stageFiles(j.stage, "").front()) != std::string::npos) note = n;
        }
        return scoutNote_[scout] = note;
    }

    // The stages whose submission files a job's render runs: a final runs the moments stage's,
    // its scene's filter's and msm's; any other job its own stage's.
    std::vector<std::string> stagesRun(const Job& job) const {
        if (job.stage == "final") return {"moments", scenes_[job.scene].filter, "msm"};
        return {job.stage};
    }

    // skipIf of job k: true (with the reason in notRunReason) if a scout showed a stage it
    // renders from the submission to be the stub.
    bool stubbedElsewhere(size_t k) {
        Job& job = jobs_[k];
        std::string reason;
        for (const auto& stage : stagesRun(job)) {
            const auto scout = scouts_.find(stage);
            if (scout == scouts_.end() || scout->second == k) continue;
            const auto note = scoutNote(scout->second);
            if (!note || note->empty()) continue;
            const GradedScene& seen = scenes_[jobs_[scout->second].scene];
            const std::string where = stage == "msm" ? std::string("on every hard case")
                                      : seen.hidden ? std::string("everywhere in another scene's render")
                                                    : "everywhere in the render of " + seen.name;
            reason += *note + "; " + where + "\n";
        }
        if (reason.empty()) return false;
        job.notRunReason = reason + "(not rendered: it would show the stub too)\n";
        return true;
    }

    // The test's scene as results.json names it.
    std::string testScene(const Job& j) const { return j.stage == "robustness" ? "hard cases" : scenes_[j.scene].name; }

    std::map<std::string, size_t> scouts_;      // stage -> the job that speaks for it
    std::map<size_t, std::string> scoutNote_;   // finished scout -> its stub note, "" if none
    const bool timing_ = std::getenv("SHADOWLAB_GRADER_TIMING") != nullptr;  // per-job times too

    // Files a stage's render compiles from the submission.
    std::vector<std::string> neededFiles(const std::string& stage, const std::string& filter) const {
        // Without reference/, lighting takes relativeDepth from the submission's moments.glsl.
        if (stage == "msm" && !haveRef_) return {"msm.glsl", "moments.glsl"};
        return stageFiles(stage, filter);
    }

    fs::path referenceFile(size_t scene, const std::string& image) const {
        const fs::path refs = o_.referenceImages.empty() ? workDir(o_) / "ref" : o_.referenceImages;
        if (mode_ == "live") return refs / scenes_[scene].name / (image + ".raw");
        const fs::path decoded = workDir(o_) / "golden" / scenes_[scene].name / (image + ".raw");
        std::error_code ec;
        if (fs::exists(decoded, ec)) return decoded;
        return goldenFolder(scenes_[scene], goldens_) / scenes_[scene].name / (image + ".exr");
    }

    // Golden mode: each scene's golden EXRs decoded once, by a child process, into
    // OUT/.work-<pid>/golden/<scene>/<image>.raw (the same floats), which the probe check, the
    // scoring and the workers' inputs then read. Reading an EXR here would start OpenEXR's
    // thread pool in this process, after which no worker can be forked (isolation.h): each was
    // exec'd, and each that read a golden loaded the image codec again. An image that does not
    // decode is read from its EXR as before (same messages).
    void decodeGoldens() {
        std::vector<ChildSpec> specs;
        for (const auto& scene : scenes_) {
            const fs::path from = goldenFolder(scene, goldens_) / scene.name;
            const fs::path to = workDir(o_) / "golden" / scene.name;
            fs::create_directories(to);
            ChildSpec spec;
            spec.logPath = to / "log.txt";
            spec.run = [from, to] {
                std::error_code ec;
                for (const auto& f : fs::directory_iterator(from, ec)) {
                    if (f.path().extension() != ".exr") continue;
                    const fs::path raw = to / (f.path().stem().string() + ".raw");
                    try {
                        writeRaw(readAnyImage(f.path()), raw.string() + ".part");
                        fs::rename(raw.string() + ".part", raw);
                    } catch (const std::exception&) {
                    }
                }
                return 0;
            };
            specs.push_back(spec);
        }
        runChildren(specs, {kTimeoutDefault, o_.memoryMb}, o_.jobs);
    }

    // Runs the jobs at `which` (indices into jobs_), two at a time; scores as they end.
    void runPhase(const std::vector<size_t>& which) {
        std::vector<ChildSpec> specs;
        std::vector<size_t> index;
        for (size_t k : which) {
            Job& j = jobs_[k];
            if (!j.missing.empty()) continue;
            fs::create_directories(j.out);
            const char* input = j.stage == "msm" ? "moments_filtered" : "moments_raw";
            specs.push_back(workerSpec(o_, scenes_[j.scene], j.stage,
                                       referenceFile(j.scene, input), j.out));
            const double ref = refSeconds_.count(j.scene) ? refSeconds_.at(j.scene) : 0.0;
            specs.back().timeoutSeconds = j.stage == "reference" ? referenceTimeout(o_) : stageTimeout(o_, ref);
            specs.back().limitNote = j.stage == "reference" ? "" : timeoutNote(o_, ref);
            if (j.stage != "reference") specs.back().skipIf = [this, k] { return stubbedElsewhere(k); };
            // Once a stage whose files a final runs has timed out (it loops), the finals not
            // started yet would wait out their limits too.
            if (j.stage == "final") specs.back().alsoRuns = stagesRun(j);
            index.push_back(k);
        }
        // A scoring error fails the grade (results.json says why), once every child has ended.
        std::exception_ptr failed;
        auto results = runChildren(specs, {kTimeoutDefault, o_.memoryMb}, o_.jobs,
                                   [&](size_t i, const ChildResult& r) {
                                       jobs_[index[i]].child = r;
                                       jobs_[index[i]].ran = true;
                                       if (timing_)
                                           std::cerr << "grade: " << jobs_[index[i]].stage << " "
                                                     << testScene(jobs_[index[i]]) << ": "
                                                     << (r.notRun ? "not run (a stub)" : std::to_string(r.seconds) + " s")
                                                     << "\n";
                                       if (jobs_[index[i]].stage == "reference" || failed) return;
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
            if (j.stage == "reference") refSeconds_[j.scene] = j.child.seconds;
            if (running_.is_null() && j.child.kind == ChildResult::Exited && j.child.exitCode == 0) {
                std::ifstream in(j.out / "worker.json");
                try { running_ = nlohmann::json::parse(in); } catch (...) {}
            }
        }
    }

    // Scores the tests of jobs_ in order, as far as their renders are done (a job with a
    // missing file has nothing to render; a dropped one has no test).
    void scoreReady() {
        for (; scored_ < jobs_.size(); ++scored_) {
            const Job& j = jobs_[scored_];
            if (j.stage == "reference" || j.dropped) continue;
            if (!j.ran && j.missing.empty()) return;
            tests_.push_back(score(j, report_.get()));
        }
    }

    // Returns the fraction of the test's points in `fraction` (assignPoints scales it).
    TestResult score(const Job& job, ReportWriter* report) {
        const GradedScene& gs = scenes_[job.scene];
        TestResult t;
        t.scene = testScene(job);  // one name, pass or fail
        t.stage = job.stage;
        t.hidden = job.stage != "robustness" && gs.hidden;
        if (!job.missing.empty()) {
            t.output = job.missing;
            return t;
        }
        if (job.child.notRun) {
            t.output = "not implemented: " + job.notRunReason;
            return t;
        }
        if (!(job.child.kind == ChildResult::Exited && job.child.exitCode == 0)) {
            t.output = failureText(job.child, o_);
            return t;
        }
        nlohmann::json worker;
        try {
            std::ifstream in(job.out / "worker.json");
            worker = nlohmann::json::parse(in);
        } catch (const std::exception&) {
            t.output = "the render left no result";
            return t;
        }
        if (job.stage == "robustness") return scoreRobustness(t, worker);
        // Stub notes naming the submission's files of this stage: not implemented.
        std::string notes;
        for (const auto& n : worker.value("stubNotes", std::vector<std::string>{}))
            for (const auto& f : stageFiles(job.stage, gs.filter))
                if (n.find("submission/" + f) != std::string::npos) notes += n + "\n";

        const std::string prefix = stageImage(job.stage);
        std::vector<std::string> images;
        for (const auto& name : worker.value("images", std::vector<std::string>{}))
            if (name.rfind(prefix, 0) == 0 && (prefix != "moments_filtered" || name == prefix))
                images.push_back(name);
        if (images.empty()) images.push_back(prefix);
        double fraction = 1.0, worstCap = 1.0;
        std::ostringstream detail;
        for (const auto& name : images) {
            Image ref, mine;
            const bool ladder = name == kDepthLadderImage;
            try {
                // msm is compared with the reference lit from the same moments (msm_<image>);
                // the relativeDepth ladder with its exact moments.
                ref = ladder ? depthLadderExpected()
                             : readAnyImage(referenceFile(job.scene, job.stage == "msm" ? "msm_" + name : name));
            } catch (const std::exception& e) {
                t.output = "no reference image " + name + " to compare with (" + e.what() + ")";
                return t;
            }
            try {
                mine = readRaw(job.out / (name + ".raw"));
            } catch (const std::exception&) {
                fraction = 0.0;
                detail << name << ": no image was produced\n";
                continue;
            }
            if (ladder && depthLadderStub(mine)) {
                notes += "submission/moments.glsl: relativeDepth: not implemented yet (it returns "
                         "the stub value -1)\n";
                continue;
            }
            Comparison c = compare(job, mine, ref);
            fraction = std::min(fraction, c.error.empty() ? c.fraction : 0.0);
            if (auto cap = rubric_.worstTexelCap.find(job.stage);
                cap != rubric_.worstTexelCap.end() && c.worst > rubric_.worstTexelFactor)
                worstCap = std::min(worstCap, cap->second);
            t.metrics[name] = c.toJson();
            t.images.push_back(name);
            detail << name << ": " << fmt(100.0 * c.fraction, 2) << "% within tolerance"
                   << "; OIIO mean " << fmt(c.mean, 6) << ", RMS " << fmt(c.rms, 6) << ", max "
                   << fmt(c.max, 6) << ", PSNR " << fmt(c.psnr, 1) << " dB";
            if (!c.error.empty()) detail << "; " << c.error;
            if (c.worstX >= 0) detail << "; worst texel at " << fmt(std::min(c.worst, 1e6), 4) << "x the tolerance";
            if (c.nonFinite) detail << "; " << c.nonFinite << " NaN/Inf values (counted wrong)";
            if (c.stubTexels) detail << "; " << c.stubTexels << " texels hold the stub value -1";
            detail << "\n";
            if (c.worstX >= 0 && c.worst > 1.0) detail << worstTexelText(name, c) << "\n";
            if (report) report->add(t, name, ref, mine, c);
        }
        t.fraction = notes.empty() ? std::min(rubric_.points(job.stage, fraction, 1.0), worstCap) : 0.0;
        const auto [pass, zero] = rubric_.ramp(job.stage);
        std::string head;
        if (!notes.empty()) head = "not implemented: " + notes;
        else if (t.fraction >= 1.0) head = "full marks\n";
        else if (worstCap < 1.0 && t.fraction == worstCap)
            head = "worst-texel rule: a texel is off by more than " + fmt(rubric_.worstTexelFactor, 0) +
                   "x the tolerance (look at the borders and edges), at most " +
                   fmt(100.0 * worstCap, 0) + "% of the points; " + fmt(100.0 * fraction, 3) +
                   "% of the texels within tolerance\n";
        else head = fmt(100.0 * fraction, 2) + "% within tolerance (full marks from " +
                    fmt(100.0 * pass, 1) + "%, none at " + fmt(100.0 * zero, 1) + "%)\n";
        if (notes.empty() && fraction == 0.0 && detail.str().find("stub value") != std::string::npos)
            head = "not implemented (the output is the stub value -1)\n";
        t.output = head + detail.str();
        return t;
    }

    // The hard-case catalogue: the fraction of cases with no NaN, Inf, out-of-range,
    // non-monotone or off-bound G (docs/numerics.md), and the failing cases with their inputs.
    TestResult scoreRobustness(TestResult t, const nlohmann::json& worker) {
        t.scene = "hard cases";
        t.hidden = false;
        const auto& r = worker["robustness"];
        const double fraction = r.value("score", 0.0);
        const auto notes = worker.value("stubNotes", std::vector<std::string>{});
        t.fraction = notes.empty() ? rubric_.points("robustness", fraction, 1.0) : 0.0;
        t.metrics["robustness"] = r;
        const auto [pass, zero] = rubric_.ramp("robustness");
        std::string head = !notes.empty() ? "not implemented: " + notes.front() + "\n"
                           : t.fraction >= 1.0 ? std::string("full marks\n")
                           : fmt(100.0 * fraction, 2) + "% of the hard cases pass (full marks from " +
                                 fmt(100.0 * pass, 1) + "%, none at " + fmt(100.0 * zero, 1) + "%)\n";
        t.output = head + r.value("summary", std::string());
        return t;
    }

    Comparison compare(const Job& job, const Image& mine, const Image& ref) {
        if (job.stage == "msm") return compareImages(mine, ref, rubric_.shadowTol);
        if (job.stage == "final") return compareImages(mine, ref, rubric_.finalTol);
        std::vector<double> extra;
        if (job.stage == "sat" && rubric_.satRounding > 0) {
            // A float32 table's rounding grows with its entries (up to the sum of the whole
            // map), and a correct table summed in another order rounds differently: allow
            // satRounding ulps of the total, spread over the box.
            Scene scene = loadScene(scenes_[job.scene].path.string());
            const double area = double(scene.shadow.satKernelTexels) * scene.shadow.satKernelTexels;
            extra.assign(ref.channels, 0.0);
            for (size_t i = 0; i < ref.pixels.size(); ++i)
                extra[i % ref.channels] += std::fabs(ref.pixels[i]);
            for (double& e : extra) e = rubric_.satRounding * std::ldexp(e, -24) / area;
        }
        if (job.stage == "moments")
            return compareMoments(mine, ref, rubric_.momentsAbs, rubric_.momentsRel);
        return compareMoments(mine, ref, rubric_.filterAbs, rubric_.filterRel, extra);
    }

    const GradeOptions& o_;
    const Rubric& rubric_;
    IntakeResult intake_;
    std::vector<GradedScene> scenes_;
    bool haveRef_ = false;
    std::string mode_;
    fs::path goldens_;
    nlohmann::json running_;  // backend/renderer/Mesa of the workers
    std::map<size_t, double> refSeconds_;  // scene -> its reference render's seconds
    TimedOutGroups timedOut_;  // stage -> its first timeout, over every phase of stage renders
    std::vector<Job> jobs_;                // every render, in scoring order
    size_t scored_ = 0;                    // jobs_[0, scored_) are scored
    std::vector<TestResult> tests_;
    std::unique_ptr<ReportWriter> report_;
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
        s.warnings.push_back(std::string("grader failed: ") + e.what());
        s.seconds = seconds();
        writeFailureResults(results, e.what(), s.seconds);
    } catch (...) {
        s = {};
        s.failed = true;
        s.warnings.push_back("grader failed: unknown error");
        writeFailureResults(results, "unknown error", seconds());
    }
    return s;
}

}  // namespace sl::grader
