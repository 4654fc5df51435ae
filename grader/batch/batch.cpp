// batch: a TA's folder of submissions. Each submission is graded by a child process (a fork
// of the batch grading it as `grade --submission` would, or that command exec'd), N at a
// time; each of those renders in its own child
// processes, one at a time when N > 1, so N workers run in all. A child that crashes or hangs
// costs its own submission only: the batch writes a results.json saying so, and a row with the
// reason.
#include "batch.h"

#include "batch_store.h"
#include "gradebook.h"

#include "image_codec.h"
#include "isolation.h"
#include "jobs.h"
#include "results.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>

#include <sys/resource.h>
#include <unistd.h>

namespace sl::grader {
namespace {

void progress(size_t done, size_t total, const std::string& last) {
    const int width = 30;
    const int filled = total ? int(width * done / total) : width;
    std::cerr << "\r[" << std::string(size_t(filled), '#') << std::string(size_t(width - filled), '.')
              << "] " << done << "/" << total << "  " << last.substr(0, 30) << "\033[K" << std::flush;
}

// `shadowlab grade` for one submission, with the batch's options: forked, gradeAndPrint(o);
// exec'd, the hidden `grade-submission` with the same options as JSON.
ChildSpec gradeSpec(const GradeOptions& o, const fs::path& logPath) {
    ChildSpec spec;
    spec.args = {"--backend", o.backend, "grade-submission", "--options", o.toJson().dump()};
    spec.logPath = logPath;
    // Forked without exec where that is safe (isolation.h): the child inherits the driver and
    // the image codec the batch has loaded, where an exec'd grade loads both again.
    spec.run = [o] { return gradeAndPrint(o); };
    return spec;
}

}  // namespace

int gradeAndPrint(const GradeOptions& o) {
    const GradeSummary s = gradeSubmission(o);
    if (!o.rowFile.empty()) {
        BatchRow row = batchRow(s);
        row.report = o.report && !s.failed;
        std::ofstream(o.rowFile) << row.toJson().dump() << "\n";
    }
    if (!s.failed) printScoreTable(std::cout, s);
    std::cout << "results: " << (o.out / "results.json").string();
    if (o.report && !s.failed) std::cout << ", report: " << (o.out / "report" / "index.html").string();
    std::cout << "\n";
    for (const auto& w : visibleSummary(s).warnings) std::cerr << "warning: " << w << "\n";
    return s.failed ? 1 : 0;
}

BatchRow batchRow(const GradeSummary& s) {
    BatchRow row;
    row.failed = s.failed || s.tests.empty();
    if (s.failed) {
        // results.json's reason, its first line.
        const std::string why = "The grader could not grade this submission: " + s.failure;
        row.notes.push_back(why.substr(0, why.find('\n')));
        return row;
    }
    // The points as results.json rounds them.
    row.score = round2(s.score);
    for (const auto& t : s.tests) {
        row.maxScore += round2(t.maxScore);
        row.stagePoints[t.stage] += round2(t.score);
        row.stageMax[t.stage] += round2(t.maxScore);
        if (t.lostPoints())
            row.lost.push_back(t.scene + " " + t.stage + " -" + fixedDigits(round2(t.maxScore) - round2(t.score)));
    }
    // One line a note: a warning's first line, and later ones written as warnings of their own.
    const VisibleSummary v = visibleSummary(s);
    auto note = [&row](const std::string& warning) {
        const std::string text = "warning: " + warning;
        for (size_t at = 0; at < text.size();) {
            size_t end = text.find('\n', at);
            if (end == std::string::npos) end = text.size();
            const std::string line = text.substr(at, end - at);
            if (line.rfind("warning: ", 0) == 0) row.notes.push_back(line.substr(9));
            at = end + 1;
        }
    };
    for (const auto& w : v.warnings) note(w);
    if (!v.hiddenWarnings.empty())
        note(std::to_string(v.hiddenWarnings.size()) + " about hidden scenes (for the course staff)");
    return row;
}

namespace {

// The reference's renders for this setup, made once and kept in OUT/.reference-<digest>: a
// batch started again, or another shard of it, uses them. Made in a folder of this process's
// own and renamed into place, so a folder of that name is always complete.
fs::path referenceRenders(const GradeOptions& base, const std::string& setup) {
    const fs::path done = base.out / (".reference-" + setup.substr(0, 16));
    std::error_code ec;
    if (fs::is_regular_file(done / "times.json", ec)) return done;
    char host[256] = "host";
    ::gethostname(host, sizeof host - 1);
    const std::string me = std::string(host) + "-" + std::to_string(::getpid());  // shards on many nodes
    const fs::path part = base.out / (".reference-part-" + me);
    fs::remove_all(part, ec);
    std::cerr << "rendering the reference scenes once...\n";
    GradeOptions r = base;
    r.out = base.out / (".reference-work-" + me);
    renderReferenceImages(r, part);
    fs::rename(part, done, ec);
    if (ec) fs::remove_all(part, ec);  // another shard's renders came first: the same images
    return done;
}

// User + sys of this process's reaped children (and theirs).
double childrenCpuSeconds() {
    struct rusage u {};
    ::getrusage(RUSAGE_CHILDREN, &u);
    auto secs = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
    return secs(u.ru_utime) + secs(u.ru_stime);
}

bool reservedName(const std::string& name) {
    return name == "scores.csv" || name == "index.html" || name == "class.html";
}

}  // namespace

BatchOutcome gradeBatch(const BatchOptions& batch, const GradeOptions& base) {
    BatchOutcome outcome;
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(batch.dir)) {
        const std::string name = e.path().filename().string();
        if (e.is_directory() && !e.is_symlink() && name[0] != '.') names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    fs::create_directories(base.out);
    const std::string setup = setupDigest(base);
    std::vector<std::string> digests(names.size());
    std::vector<size_t> todo;  // this shard's submissions with no row under their digest
    for (size_t i = 0; i < names.size(); ++i) {
        digests[i] = rowDigest(submissionDigest(batch.dir / names[i]), setup);
        const bool mine = int(i % size_t(batch.shards)) == batch.shard - 1;
        if (storedRow(base.out, names[i], digests[i])) {
            if (mine) ++outcome.reused;
        } else if (mine && !batch.mergeOnly && reservedName(names[i])) {
            BatchRow row;
            row.failed = true;
            row.notes.push_back("the folder's name is one of the batch's own files: rename it");
            writeFailureResults(base.out / names[i] / "results.json", row.notes.back(), 0.0);
            row.digest = digests[i];
            storeRow(base.out, names[i], row);
            ++outcome.graded;
        } else if (mine && !batch.mergeOnly) {
            todo.push_back(i);
        }
    }

    GradeOptions shared = base;
    const double cpuBefore = childrenCpuSeconds();
    if (!todo.empty() && resolveReferenceMode(base.reference) == "live")
        shared.referenceImages = referenceRenders(base, setup);
    outcome.referenceCpuSeconds = childrenCpuSeconds() - cpuBefore;
    std::vector<ChildSpec> specs;
    for (size_t i : todo) {
        GradeOptions o = shared;
        o.submission = batch.dir / names[i];
        o.out = base.out / names[i];
        o.jobs = batch.parallel > 1 ? 1 : base.jobs;
        o.rowFile = o.out / ".row.json";  // the child's row, stored with its digest once it ends
        std::error_code ec;
        fs::remove_all(o.out, ec);  // a report of an earlier grade must not outlive it
        fs::create_directories(o.out, ec);
        specs.push_back(gradeSpec(o, base.out / (names[i] + ".log")));
    }
    // A row from what the child left (its row file, or how it ended), stored as soon as it ends.
    auto store = [&](size_t k, const ChildResult& c) {
        const size_t i = todo[k];
        const fs::path sub = base.out / names[i];
        BatchRow row;
        const bool exited = c.kind == ChildResult::Exited && (c.exitCode == 0 || c.exitCode == 1);
        std::ifstream in(sub / ".row.json");
        const nlohmann::json r = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
        bool read = false;
        if (exited && r.is_object()) {
            try {
                row = BatchRow::fromJson(r);
                read = true;
            } catch (const std::invalid_argument&) {
            }
        }
        if (!read) {
            const std::string why =
                c.kind == ChildResult::Signalled ? "the grader crashed (" + signalName(c.signal) + ")"
                : c.kind == ChildResult::TimedOut ? "the grader did not finish in 1800 s"
                : "the grader stopped (exit " + std::to_string(c.exitCode) + ")";
            writeFailureResults(sub / "results.json", why, c.seconds);
            row = BatchRow();
            row.failed = true;
            row.notes.push_back(why);
        }
        std::error_code ec;
        fs::remove(sub / ".row.json", ec);
        row.digest = digests[i];
        storeRow(base.out, names[i], row);
        ++outcome.graded;
        outcome.cpuSeconds.push_back(c.cpuSeconds);
    };
    size_t done = 0;
    if (!todo.empty()) {
        progress(0, todo.size(), "");
        // A whole submission's limit: generous, only against a grader that never returns.
        const Limits limits{1800.0, 2 * base.memoryMb};
        // Loaded once here, not in every submission's child (log4cplus starts idle threads).
        loadBeforeForking([] { imageCodec(); });
        runChildren(specs, limits, std::max(1, batch.parallel), [&](size_t k, const ChildResult& c) {
            store(k, c);
            progress(++done, todo.size(), names[todo[k]]);
        });
        std::cerr << "\n";
    }

    // The gradebook, of every submission, from the rows alone (gradebook.h); a shard leaves it
    // to the merge.
    std::vector<GradebookEntry> entries;
    for (size_t i = 0; i < names.size(); ++i) {
        entries.push_back({names[i], storedRow(base.out, names[i], digests[i])});
        if (!entries.back().row) outcome.missing.push_back(names[i]);
    }
    outcome.submissions = names.size();
    if (batch.shards == 1 || batch.mergeOnly) {
        writeGradebook(base.out, entries);
        outcome.wroteGradebook = true;
    }
    return outcome;
}

}  // namespace sl::grader
