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

// `shadowlab grade` for one submission, with the batch's options.
ChildSpec gradeSpec(const GradeOptions& o, const fs::path& logPath) {
    std::vector<std::string> a = {"--backend", o.backend, "grade",
                                  "--submission", o.submission.string(),
                                  "--out", o.out.string(),
                                  "--reference", o.reference,
                                  "--memory", std::to_string(o.memoryMb),
                                  "-j", std::to_string(o.jobs)};
    if (o.timeoutSeconds > 0) a.insert(a.end(), {"--timeout", std::to_string(o.timeoutSeconds)});
    if (!o.scenes.empty()) {
        std::string list;
        for (const auto& s : o.scenes) list += (list.empty() ? "" : ",") + s;
        a.insert(a.end(), {"--scenes", list});
    }
    if (!o.goldens.empty()) a.insert(a.end(), {"--goldens", o.goldens.string()});
    if (!o.rubric.empty()) a.insert(a.end(), {"--rubric", o.rubric.string()});
    if (!o.referenceImages.empty())
        a.insert(a.end(), {"--reference-images", o.referenceImages.string()});
    if (!o.report) a.push_back("--no-report");
    if (o.keepWork) a.push_back("--keep-work");
    ChildSpec spec;
    spec.args = a;
    spec.logPath = logPath;
    // Forked without exec where that is safe (isolation.h): the child inherits the driver and
    // the image codec the batch has loaded, where an exec'd grade loads both again. The same
    // options as the command line above, which is exec'd where a fork is not safe.
    spec.run = [o] { return gradeAndPrint(o); };
    return spec;
}

}  // namespace

int gradeAndPrint(const GradeOptions& o) {
    const GradeSummary s = gradeSubmission(o);
    if (!s.failed) printScoreTable(std::cout, s);
    std::cout << "results: " << (o.out / "results.json").string();
    if (o.report && !s.failed) std::cout << ", report: " << (o.out / "report" / "index.html").string();
    std::cout << "\n";
    for (const auto& w : visibleSummary(s).warnings) std::cerr << "warning: " << w << "\n";
    return s.failed ? 1 : 0;
}

GradeSummary summaryFromResults(const nlohmann::json& r) {
    GradeSummary s;
    if (!r.is_object()) return s;
    s.score = r.value("score", 0.0);
    for (const auto& t : r.value("tests", nlohmann::json::array())) {
        TestResult x;
        for (const auto& tag : t.value("tags", std::vector<std::string>{})) {
            if (tag.rfind("stage:", 0) == 0) x.stage = tag.substr(6);
            if (tag.rfind("scene:", 0) == 0) x.scene = tag.substr(6);
        }
        x.score = t.value("score", 0.0);
        x.maxScore = t.value("max_score", 0.0);
        s.maxScore += x.maxScore;
        s.tests.push_back(x);
    }
    const std::string output = r.value("output", std::string());
    for (size_t at = 0; at < output.size();) {
        size_t end = output.find('\n', at);
        if (end == std::string::npos) end = output.size();
        const std::string line = output.substr(at, end - at);
        if (line.rfind("warning: ", 0) == 0) s.warnings.push_back(line.substr(9));
        at = end + 1;
    }
    if (s.tests.empty()) {
        s.failed = true;
        if (s.warnings.empty()) s.warnings.push_back(output.substr(0, output.find('\n')));
    }
    return s;
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
    for (const auto& sub : subs) {
        GradeOptions o = shared;
        o.submission = sub;
        o.out = base.out / sub.filename();
        o.jobs = parallel > 1 ? 1 : base.jobs;
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

    std::vector<GradeSummary> summaries(subs.size());
    for (size_t i = 0; i < subs.size(); ++i) {
        const fs::path results_json = base.out / subs[i].filename() / "results.json";
        const ChildResult& c = results[i];
        const bool exited = c.kind == ChildResult::Exited && (c.exitCode == 0 || c.exitCode == 1);
        std::ifstream in(results_json);
        nlohmann::json r = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
        if (!exited || !r.is_object()) {
            const std::string why =
                c.kind == ChildResult::Signalled ? "the grader crashed (" + signalName(c.signal) + ")"
                : c.kind == ChildResult::TimedOut ? "the grader did not finish in 1800 s"
                : "the grader stopped (exit " + std::to_string(c.exitCode) + ")";
            writeFailureResults(results_json, why, c.seconds);
            summaries[i].failed = true;
            summaries[i].warnings.push_back(why);
            continue;
        }
        summaries[i] = summaryFromResults(r);
    }

    std::ofstream csv(base.out / "scores.csv");
    csv << "submission,total,max";
    for (const auto& stage : stageNames()) csv << "," << stage;
    csv << ",notes\n";
    for (size_t i = 0; i < subs.size(); ++i) {
        const auto& s = summaries[i];
        const auto totals = stageTotals(s);
        csv << csvField(subs[i].filename().string()) << "," << points(s.score) << ","
            << points(s.maxScore);
        for (const auto& stage : stageNames()) {
            auto it = totals.find(stage);
            csv << "," << (it == totals.end() ? "" : points(it->second.first));
        }
        std::string notes;
        for (const auto& w : s.warnings) notes += (notes.empty() ? "" : "; ") + w;
        csv << "," << csvField(notes) << "\n";
    }
    return int(subs.size());
}

}  // namespace sl::grader
