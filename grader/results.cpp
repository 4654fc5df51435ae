// results: the Gradescope results format (score, execution_time, output, tests[] with name,
// score, max_score, status, output, visibility, tags) and the per-stage table students see.
#include "results.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace sl::grader {
namespace {

double round2(double v) { return std::round(v * 100.0) / 100.0; }

}  // namespace

std::map<std::string, std::pair<double, double>> stageTotals(const GradeSummary& s) {
    std::map<std::string, std::pair<double, double>> totals;
    for (const auto& t : s.tests) {
        totals[t.stage].first += t.score;
        totals[t.stage].second += t.maxScore;
    }
    return totals;
}

nlohmann::json resultsJson(const GradeSummary& s, const Rubric& rubric) {
    nlohmann::json tests = nlohmann::json::array();
    for (const auto& t : s.tests) {
        const bool passed = t.score >= t.maxScore - 1e-9;
        nlohmann::json j = {{"name", t.scene + ": " + t.stage},
                            {"score", round2(t.score)},
                            {"max_score", round2(t.maxScore)},
                            {"status", passed ? "passed" : "failed"},
                            {"output", t.output},
                            {"visibility", t.hidden ? rubric.hiddenVisibility : rubric.visibility},
                            {"tags", {"stage:" + t.stage, "scene:" + t.scene}}};
        tests.push_back(j);
    }
    std::ostringstream out;
    out << "Shadowlab grade: " << std::fixed << std::setprecision(2) << s.score << " / "
        << s.maxScore << " (reference: " << s.referenceMode << ")\n";
    for (const auto& w : s.warnings) out << "warning: " << w << "\n";
    return {{"score", round2(s.score)},
            {"execution_time", int(std::ceil(s.seconds))},
            {"output", out.str()},
            {"stdout_visibility", "visible"},
            {"tests", tests}};
}

void writeResults(const std::filesystem::path& path, const nlohmann::json& results) {
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
    const auto tmp = path.string() + ".tmp";
    {
        std::ofstream out(tmp);
        // NaN cannot appear in JSON: replace invalid numbers rather than fail to write.
        out << results.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    }
    std::filesystem::rename(tmp, path, ec);
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
    out << "\n  stage       points      lost on\n"
        << "  ----------  ----------  -------------------------------------------\n";
    const auto totals = stageTotals(s);
    for (const auto& stage : stageNames()) {
        auto it = totals.find(stage);
        if (it == totals.end()) continue;
        std::string lost;
        for (const auto& t : s.tests)
            if (t.stage == stage && t.score < t.maxScore - 1e-9) {
                std::string why = t.output.substr(0, t.output.find('\n'));
                if (why.size() > 60) why = why.substr(0, 57) + "...";
                lost += (lost.empty() ? "" : "\n                          ") + t.scene + ": " + why;
            }
        char pts[32];
        std::snprintf(pts, sizeof pts, "%5.1f/%-5.1f", it->second.first, it->second.second);
        out << "  " << std::left << std::setw(10) << stage << "  " << pts << "  "
            << (lost.empty() ? "full marks" : lost) << "\n";
    }
    char total[64];
    std::snprintf(total, sizeof total, "%5.1f/%-5.1f", s.score, s.maxScore);
    out << "  ----------  ----------\n  total       " << total << "  (" << std::fixed
        << std::setprecision(1) << s.seconds << " s, reference: " << s.referenceMode << ")\n";
    for (const auto& w : s.warnings) out << "  warning: " << w << "\n";
}

}  // namespace sl::grader
