// cli_grade: the grader's subcommands.
//   grade         grade one submission (--submission) or a folder of them (--batch)
//   golden        (re)make or check the golden images
//   package       the student kit (.tar.gz) or the Gradescope autograder (.zip)
//   grade-submission  hidden: one submission of a batch, exec'd (batch.cpp); not for people
//   grade-worker  hidden: one child process's render (worker.cpp); not for people
#include "batch.h"
#include "cli_commands.h"
#include "golden.h"
#include "out_guard.h"
#include "package.h"
#include "grader.h"
#include "paths.h"
#include "results.h"
#include "study_shard.h"
#include "worker.h"

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace sl::cli {

void addGraderCommands(CLI::App& app, Context& ctx) {
    using namespace sl::grader;
    auto* grade = app.add_subcommand("grade", "grade a submission against the reference or goldens");
    struct GradeArgs {
        GradeOptions o;
        std::string submission, batch, out;
        int jobs = 2;
        bool noReport = false;
        std::string shard = "1/1";
        bool merge = false;
    };
    auto g = std::make_shared<GradeArgs>();
    auto* sub = grade->add_option("--submission", g->submission, "folder holding the stage files");
    auto* bat = grade->add_option("--batch", g->batch, "folder of submission folders (TA)");
    sub->excludes(bat);
    grade->add_option("--out", g->out, "output folder (results.json, report/)")->required();
    grade->add_option("--scenes", g->o.scenes,
                      "comma-separated scene names, paths to hidden scene files, and the keyword "
                      "\"public\" for every public scene (default: public)")
        ->delimiter(',');
    grade->add_option("--reference", g->o.reference, "live, golden or auto (live if reference/ exists)")
        ->check(CLI::IsMember({"live", "golden", "auto"}));
    grade->add_option("--timeout", g->o.timeoutSeconds,
                      "seconds per render (default: 10x the reference's own render of the scene, "
                      "at least 5 s; 20 s with goldens only)")
        ->check(CLI::PositiveNumber);
    grade->add_option("--memory", g->o.memoryMb, "MB of address space per render (default 4096)")
        ->check(CLI::PositiveNumber);
    grade->add_option("-j,--jobs", g->jobs, "renders (single) or submissions (batch) at a time")
        ->check(CLI::Range(1, 64));
    grade->add_option("--goldens", g->o.goldens, "golden folder (default scenes/goldens)");
    grade->add_option("--rubric", g->o.rubric, "rubric JSON (default grader/rubric.json)");
    grade->add_flag("--no-report", g->noReport, "skip the HTML report");
    grade->add_flag("--keep-work", g->o.keepWork, "keep OUT/.work-<pid> (worker images and logs)");
    grade->add_option("--shard", g->shard, "batch: grade only the K-th of every N submissions (K/N), "
                                           "leaving the gradebook to --merge (a Slurm array's task)");
    grade->add_flag("--merge", g->merge, "batch: grade nothing; write scores.csv, index.html and "
                                         "class.html of what the shards graded into OUT");
    grade->add_option("--reference-images", g->o.referenceImages)->group("");  // batch children
    grade->callback([g, &ctx] {
        if (g->submission.empty() == g->batch.empty())
            throw CLI::ValidationError("grade", "give --submission DIR or --batch DIR");
        GradeOptions o = g->o;
        o.out = g->out;
        // OUT may not be (or hold, or sit in) the submission, scenes/, reference/, goldens.
        const std::string outProblem = outFolderProblem(
            o.out, guardedFolders(g->batch.empty() ? fs::path(g->submission) : fs::path(g->batch), o.goldens));
        if (!outProblem.empty()) {
            std::cerr << "error: " << outProblem << "\n";
            ctx.exitCode = BadInput;
            return;
        }
        o.backend = ctx.backend;
        o.report = !g->noReport;
        if (!g->batch.empty()) {
            BatchOptions b;
            b.dir = g->batch;
            b.parallel = g->jobs;
            b.mergeOnly = g->merge;
            try {
                parseShard(g->shard, b.shard, b.shards);
            } catch (const std::invalid_argument& e) {
                throw CLI::ValidationError("--shard", e.what());
            }
            if (b.mergeOnly && b.shards > 1) throw CLI::ValidationError("--merge", "give --merge without --shard");
            const BatchOutcome r = gradeBatch(b, o);
            std::cout << (b.shards > 1 ? "shard " + g->shard + ": " : "") << "graded " << r.graded
                      << ", already graded " << r.reused << " (their rows kept)";
            if (r.wroteGradebook)
                std::cout << "; " << r.submissions << " submissions in " << (o.out / "scores.csv").string()
                          << ", " << (o.out / "index.html").string() << ", " << (o.out / "class.html").string();
            std::cout << "\n";
            if (!r.cpuSeconds.empty()) {
                std::vector<double> c = r.cpuSeconds;
                std::sort(c.begin(), c.end());
                std::fprintf(stderr, "CPU per submission (user + sys, its processes): median %.2f s, min %.2f, "
                             "max %.2f over %zu; the reference's renders %.2f s\n", c[c.size() / 2], c.front(),
                             c.back(), c.size(), r.referenceCpuSeconds);
            }
            if (r.wroteGradebook && !r.missing.empty()) {
                std::cout << r.missing.size() << " not graded yet:";
                for (size_t i = 0; i < r.missing.size() && i < 10; ++i) std::cout << " " << r.missing[i];
                std::cout << (r.missing.size() > 10 ? " ..." : "") << "\n";
            }
            ctx.exitCode = r.wroteGradebook && !r.missing.empty() ? Failed : Ok;
            return;
        }
        o.submission = g->submission;
        o.jobs = g->jobs;
        ctx.exitCode = gradeAndPrint(o) == 0 ? Ok : Failed;
    });

    auto* golden = app.add_subcommand("golden", "make (or --check) the golden images");
    auto go = std::make_shared<GoldenOptions>();
    go->out = repoRoot() / "scenes" / "goldens";
    golden->add_option("--solution", go->solution, "solution to render (default reference)");
    golden->add_option("--out", go->out, "public golden folder (default scenes/goldens); a hidden "
                                         "scene's goldens go to goldens/ next to its scene file");
    golden->add_option("--scenes", go->scenes,
                       "comma-separated scene names, paths to hidden scene files, and the keyword "
                       "\"public\" for every public scene (default: public)")->delimiter(',');
    golden->add_flag("--check", go->check, "compare a fresh render's encoding with the manifests");
    golden->callback([go, &ctx] {
        GoldenOptions o = *go;
        o.backend = ctx.backend;
        const GoldenRun run = runGoldens(o);
        for (const auto& m : run.messages) std::cout << m << "\n";
        if (o.check) {
            for (const auto& s : run.stale) std::cout << "stale: " << s << "\n";
            std::cout << (run.stale.empty() ? "goldens are up to date\n"
                                            : "goldens are stale: run " + run.advice + "\n");
            ctx.exitCode = run.stale.empty() ? Ok : Failed;
        } else {
            ctx.exitCode = Ok;
        }
    });

    auto* package = app.add_subcommand("package", "build the student kit or the Gradescope autograder");
    auto pk = std::make_shared<std::pair<std::string, std::string>>("student", "");
    package->add_option("--kind", pk->first, "student (tar.gz) or gradescope (zip)")
        ->check(CLI::IsMember({"student", "gradescope"}));
    package->add_option("--out", pk->second, "archive to write")->required();
    package->callback([pk, &ctx] {
        std::cout << makePackage(pk->first, pk->second) << "\n";
        ctx.exitCode = Ok;
    });

    // Hidden: one submission of a batch, exec'd where a fork is not safe (batch.cpp).
    auto* one = app.add_subcommand("grade-submission", "");
    one->group("");
    auto options = std::make_shared<std::string>();
    one->add_option("--options", *options, "GradeOptions as JSON (grader.h)")->required();
    one->callback([options, &ctx] {
        ctx.exitCode = gradeAndPrint(GradeOptions::fromJson(nlohmann::json::parse(*options))) == 0 ? Ok : Failed;
    });

    auto* worker = app.add_subcommand("grade-worker", "");
    worker->group("");  // hidden: the grader's child process
    auto job = std::make_shared<std::string>();
    worker->add_option("--job", *job, "WorkerArgs as JSON (worker.h)")->required();
    worker->callback([job, &ctx] {
        WorkerArgs a = WorkerArgs::fromJson(nlohmann::json::parse(*job));
        a.backend = ctx.backend;
        ctx.exitCode = workerMain(a);
    });
}

}  // namespace sl::cli
