// batch: a TA's folder of submissions. Submissions are graded N at a time on threads (each one
// still renders in its own child processes, one at a time when N > 1, so N workers run in all);
// a failure in one submission is its own results.json and a row with its reason.
#include "batch.h"

#include "results.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <mutex>
#include <thread>

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

}  // namespace

int gradeBatch(const fs::path& dir, int parallel, const GradeOptions& base) {
    std::vector<fs::path> subs;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.is_directory() && !e.is_symlink()) subs.push_back(e.path());
    std::sort(subs.begin(), subs.end());
    std::vector<GradeSummary> summaries(subs.size());
    GradeOptions shared = base;
    if (resolveReferenceMode(base.reference) == "live") {
        // One reference render per scene for the whole batch, not one per submission.
        shared.referenceImages = base.out / ".reference";
        std::cerr << "rendering the reference scenes once...\n";
        GradeOptions r = base;
        r.out = base.out / ".reference-work";
        renderReferenceImages(r, shared.referenceImages);
    }
    std::atomic<size_t> next{0}, done{0};
    std::mutex mu;
    progress(0, subs.size(), "");
    auto worker = [&] {
        for (size_t i; (i = next++) < subs.size();) {
            GradeOptions o = shared;
            o.submission = subs[i];
            o.out = base.out / subs[i].filename();
            o.jobs = parallel > 1 ? 1 : base.jobs;
            o.quiet = true;
            summaries[i] = gradeSubmission(o);
            std::lock_guard lock(mu);
            progress(++done, subs.size(), subs[i].filename().string());
        }
    };
    std::vector<std::thread> threads;
    for (int t = 0; t < std::max(1, parallel); ++t) threads.emplace_back(worker);
    for (auto& t : threads) t.join();
    std::cerr << "\n";

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
