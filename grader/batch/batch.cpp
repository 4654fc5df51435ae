// batch: a TA's folder of submissions. Each submission is graded by a child process (a fork
// of the batch grading it as `grade --submission` would, or that command exec'd), N at a
// time; each of those renders in its own child
// processes, one at a time when N > 1, so N workers run in all. A child that crashes or hangs
// costs its own submission only: the batch writes a results.json saying so, and a row with the
// reason.
#include "batch.h"

#include "image_codec.h"
#include "isolation.h"
#include "jobs.h"
#include "results.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace sl::grader {
namespace {

void progress(size_t done, size_t total, const std::string& last) {
    const int width = 30;
    const int filled = total ? int(width * done / total) : width;
    std::cerr << "\r[" << std::string(size_t(filled), '#') << std::string(size_t(width - filled), '.')
              << "] " << done << "/" << total << "  " << last.substr(0, 30) << "\033[K" << std::flush;
}

std::string csvField(std::string s) {
    for (char& c : s) if (c == '\n' || c == '\r') c = ' ';
    if (s.find_first_of(",\"") == std::string::npos) return s;
    std::string o = "\"";
    for (char c : s) o += c == '"' ? std::string("\"\"") : std::string(1, c);
    return o + "\"";
}

std::string points(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
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
    if (!o.rowFile.empty()) std::ofstream(o.rowFile) << batchRow(s).toJson().dump() << "\n";
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

int gradeBatch(const fs::path& dir, int parallel, const GradeOptions& base) {
    std::vector<fs::path> subs;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.is_directory() && !e.is_symlink()) subs.push_back(e.path());
    std::sort(subs.begin(), subs.end());
    GradeOptions shared = base;
    if (resolveReferenceMode(base.reference) == "live") {
        // One reference render per scene for the whole batch, not one per submission.
        shared.referenceImages = base.out / ".reference";
        std::cerr << "rendering the reference scenes once...\n";
        GradeOptions r = base;
        r.out = base.out / ".reference-work";
        renderReferenceImages(r, shared.referenceImages);
    }
    std::vector<ChildSpec> specs;
    const fs::path rows = base.out / ".rows";  // each child's BatchRow
    fs::create_directories(rows);
    for (const auto& sub : subs) {
        GradeOptions o = shared;
        o.submission = sub;
        o.out = base.out / sub.filename();
        o.jobs = parallel > 1 ? 1 : base.jobs;
        o.rowFile = rows / (sub.filename().string() + ".json");
        std::error_code ec;
        fs::create_directories(o.out, ec);
        specs.push_back(gradeSpec(o, base.out / (sub.filename().string() + ".log")));
    }
    size_t done = 0;
    progress(0, subs.size(), "");
    // A whole submission's limit: generous, only against a grader that never returns.
    const Limits limits{1800.0, 2 * base.memoryMb};
    // Loaded once here, not in every submission's child (log4cplus starts idle threads).
    loadBeforeForking([] { imageCodec(); });
    const auto results = runChildren(specs, limits, std::max(1, parallel),
                                     [&](size_t i, const ChildResult&) {
                                         progress(++done, subs.size(), subs[i].filename().string());
                                     });
    std::cerr << "\n";

    std::vector<BatchRow> table(subs.size());
    for (size_t i = 0; i < subs.size(); ++i) {
        const ChildResult& c = results[i];
        const bool exited = c.kind == ChildResult::Exited && (c.exitCode == 0 || c.exitCode == 1);
        std::ifstream in(rows / (subs[i].filename().string() + ".json"));
        const nlohmann::json r = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
        if (exited && r.is_object()) {
            try {
                table[i] = BatchRow::fromJson(r);
                continue;
            } catch (const std::invalid_argument&) {
            }
        }
        const std::string why =
            c.kind == ChildResult::Signalled ? "the grader crashed (" + signalName(c.signal) + ")"
            : c.kind == ChildResult::TimedOut ? "the grader did not finish in 1800 s"
            : "the grader stopped (exit " + std::to_string(c.exitCode) + ")";
        writeFailureResults(base.out / subs[i].filename() / "results.json", why, c.seconds);
        table[i].failed = true;
        table[i].notes.push_back(why);
    }
    std::error_code ec;
    fs::remove_all(rows, ec);

    std::ofstream csv(base.out / "scores.csv");
    csv << "submission,total,max";
    for (const auto& stage : stageNames()) csv << "," << stage;
    csv << ",notes\n";
    for (size_t i = 0; i < subs.size(); ++i) {
        const BatchRow& s = table[i];
        csv << csvField(subs[i].filename().string()) << "," << points(s.score) << ","
            << points(s.maxScore);
        for (const auto& stage : stageNames()) {
            auto it = s.stagePoints.find(stage);
            csv << "," << (it == s.stagePoints.end() ? "" : points(it->second));
        }
        std::string notes;
        for (const auto& w : s.notes) notes += (notes.empty() ? "" : "; ") + w;
        csv << "," << csvField(notes) << "\n";
    }
    return int(subs.size());
}

}  // namespace sl::grader
