// results: the Gradescope results format (score, execution_time, output, tests[] with name,
// score, max_score, status, output, visibility, tags) and the per-stage table students see.
// Hidden-scene tests are in results.json with their own visibility (Gradescope shows them
// after the due date), but nothing students see before then names a hidden scene, shows its
// errors or counts its points: the table on stdout, the top-level `output`, the warnings.
#include "results.h"

#include "out_guard.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace sl::grader {

std::string fixedDigits(double v, int digits) {
    std::ostringstream o;
    o.setf(std::ios::fixed);
    o.precision(digits);
    o << v;
    return o.str();
}
double round2(double v) { return std::round(v * 100.0) / 100.0; }

std::map<std::string, std::pair<double, double>> stageTotals(const GradeSummary& s,
                                                               bool visibleOnly) {
    std::map<std::string, std::pair<double, double>> totals;
    for (const auto& t : s.tests) {
        if (visibleOnly && t.hidden) continue;
        totals[t.stage].first += t.score;
        totals[t.stage].second += t.maxScore;
    }
    return totals;
}

VisibleSummary visibleSummary(const GradeSummary& s) {
    VisibleSummary v;
    std::vector<std::string> hiddenNames;
    for (const auto& t : s.tests) {
        if (!t.hidden) {
            v.score += t.score;
            v.maxScore += t.maxScore;
            continue;
        }
        ++v.hiddenTests;
        if (std::find(hiddenNames.begin(), hiddenNames.end(), t.scene) == hiddenNames.end())
            hiddenNames.push_back(t.scene);
    }
    // A warning about a hidden scene names it ("scene X changed since its goldens..."):
    // staff-only. Matched on the quoted or bare scene name as a word.
    auto mentions = [](const std::string& w, const std::string& name) {
        for (size_t p = w.find(name); p != std::string::npos; p = w.find(name, p + 1)) {
            auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
            const bool before = p == 0 || !word(w[p - 1]);
            const bool after = p + name.size() >= w.size() || !word(w[p + name.size()]);
            if (before && after) return true;
        }
        return false;
    };
    for (const auto& w : s.warnings) {
        bool hidden = false;
        for (const auto& n : hiddenNames) hidden = hidden || mentions(w, n);
        (hidden ? v.hiddenWarnings : v.warnings).push_back(w);
    }
    return v;
}

nlohmann::json resultsJson(const GradeSummary& s, const Rubric& rubric) {
    // The top-level output is shown to students with the visible tests: visible points only.
    const VisibleSummary v = visibleSummary(s);
    std::string staffWarnings;  // into the hidden tests' own output
    for (const auto& w : v.hiddenWarnings) staffWarnings += "warning: " + w + "\n";
    nlohmann::json tests = nlohmann::json::array();
    for (const auto& t : s.tests) {
        const bool passed = !t.lostPoints();
        nlohmann::json j = {{"name", t.scene + ": " + t.stage},
                            {"score", round2(t.score)},
                            {"max_score", round2(t.maxScore)},
                            {"status", passed ? "passed" : "failed"},
                            {"output", t.hidden ? staffWarnings + t.output : t.output},
                            {"visibility", t.hidden ? rubric.hiddenVisibility : rubric.visibility},
                            {"tags", {"stage:" + t.stage, "scene:" + t.scene}}};
        tests.push_back(j);
    }
    std::ostringstream out;
    out << "Shadowlab grade" << (v.hiddenTests ? " (visible tests)" : "") << ": " << std::fixed
        << std::setprecision(2) << v.score << " / " << v.maxScore << " (reference: "
        << s.referenceMode << ")\n";
    if (v.hiddenTests)
        out << v.hiddenTests << " more tests on hidden scenes are graded too; they are shown "
            << "after the due date\n";
    for (const auto& n : s.notes) out << n << "\n";
    for (const auto& w : v.warnings) out << "warning: " << w << "\n";
    if (!v.hiddenWarnings.empty())
        out << "warning: " << v.hiddenWarnings.size() << " about hidden scenes (for the course staff)\n";
    return {{"score", round2(s.score)},
            {"execution_time", int(std::ceil(s.seconds))},
            {"output", out.str()},
            {"stdout_visibility", "visible"},
            {"tests", tests}};
}

void writeResults(const std::filesystem::path& path, const nlohmann::json& results) {
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
    // NaN cannot appear in JSON: replace invalid numbers rather than fail to write. Through
    // a fresh temp file (O_EXCL | O_NOFOLLOW, out_guard.h): a planted link is never followed.
    writeFileSafely(path, results.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

void writeFailureResults(const std::filesystem::path& path, const std::string& reason,
                         double seconds) {
    writeResults(path, {{"score", 0},
                        {"execution_time", int(std::ceil(seconds))},
                        {"output", "The grader could not grade this submission: " + reason +
                                       "\nPlease tell the course staff."},
                        {"tests", nlohmann::json::array()}});
}

void printScoreTable(std::ostream& out, const GradeSummary& s) {
    const VisibleSummary v = visibleSummary(s);
    out << "\n  stage       points         lost on\n"
        << "  ----------  -------------  -------------------------------------------\n";
    const auto totals = stageTotals(s, true);
    for (const auto& stage : stageNames()) {
        auto it = totals.find(stage);
        if (it == totals.end()) continue;
        std::string lost;
        for (const auto& t : s.tests)
            if (t.stage == stage && !t.hidden && t.lostPoints()) {
                std::string why = t.output.substr(0, t.output.find('\n'));  // whole, never cut
                lost += (lost.empty() ? "" : "\n                             ") + t.scene + ": " + why;
            }
        char pts[32];
        std::snprintf(pts, sizeof pts, "%6.2f/%-6.2f", it->second.first, it->second.second);
        out << "  " << std::left << std::setw(10) << stage << "  " << pts << "  "
            << (lost.empty() ? "full marks" : lost) << "\n";
    }
    char total[64];
    std::snprintf(total, sizeof total, "%6.2f/%-6.2f", v.score, v.maxScore);
    out << "  ----------  -------------\n  total       " << total << "  (" << std::fixed
        << std::setprecision(1) << s.seconds << " s, reference: " << s.referenceMode << ")\n";
    if (v.hiddenTests)
        out << "  (visible tests only: " << v.hiddenTests
            << " tests on hidden scenes are graded too and shown after the due date)\n";
    for (const auto& n : s.notes) out << "  " << n << "\n";
    if (!s.findings.empty()) {
        out << "  what the failures look like:\n";
        for (const auto& f : s.findings) out << "  - " << f << "\n";
    }
    for (const auto& w : v.warnings) out << "  warning: " << w << "\n";
    if (!v.hiddenWarnings.empty())
        out << "  warning: " << v.hiddenWarnings.size() << " about hidden scenes (for the course staff)\n";
}

}  // namespace sl::grader
