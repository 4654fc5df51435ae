// points: test maxima and scores in exact hundredths; the "either" filter mode (points.h).
#include "points.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace sl::grader {
namespace {

std::string hundredthsText(long h) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%ld.%02ld", h / 100, h % 100);
    return buf;
}

double meanFraction(const std::vector<TestResult>& tests, const std::string& stage, int& count) {
    double sum = 0.0;
    count = 0;
    for (const auto& t : tests)
        if (t.stage == stage) sum += t.fraction, ++count;
    return count ? sum / count : -1.0;
}

// "either": keeps the better filter stage and drops the other, with the `final` tests of the
// scenes that use the dropped filter (rendering them needs the filter not implemented).
// Returns the chosen stage ("" when the run has no filter test).
std::string chooseFilter(GradeSummary& s) {
    int nG = 0, nS = 0;
    const double g = meanFraction(s.tests, "gaussian", nG), sat = meanFraction(s.tests, "sat", nS);
    const std::string chosen = betterFilter(s.tests);
    if (chosen.empty()) return "";
    const std::string dropped = chosen == "gaussian" ? "sat" : "gaussian";
    std::set<std::string> droppedScenes;
    for (const auto& t : s.tests)
        if (t.stage == dropped) droppedScenes.insert(t.scene);
    std::erase_if(s.tests, [&](const TestResult& t) {
        return t.stage == dropped || (t.stage == "final" && droppedScenes.count(t.scene));
    });
    char line[256];
    std::snprintf(line, sizeof line,
                  "filters: either (rubric): the filter points go to %s (gaussian %s, sat %s of "
                  "the points earned)%s",
                  chosen.c_str(), nG ? (std::to_string(int(std::lround(100 * g))) + "%").c_str() : "not in this run",
                  nS ? (std::to_string(int(std::lround(100 * sat))) + "%").c_str() : "not in this run",
                  droppedScenes.empty() ? "" : "; final is graded on the scenes that use it only");
    s.notes.push_back(line);
    return chosen;
}

}  // namespace

std::string betterFilter(const std::vector<TestResult>& tests) {
    int nG = 0, nS = 0;
    const double g = meanFraction(tests, "gaussian", nG), sat = meanFraction(tests, "sat", nS);
    if (nG == 0 && nS == 0) return "";
    return (nS == 0 || (nG > 0 && g >= sat)) ? "gaussian" : "sat";
}

long earnedHundredths(double fraction, long maxHundredths) {
    if (maxHundredths <= 0) return 0;
    if (fraction >= 1.0) return maxHundredths;
    if (!(fraction > 0.0)) return 0;
    return std::clamp(long(std::lround(fraction * double(maxHundredths))), 0L, maxHundredths - 1);
}

void assignPoints(GradeSummary& s, const Rubric& rubric) {
    Rubric r = rubric;
    s.filterMode = r.filters;
    if (r.filters == "either") {
        const std::string chosen = chooseFilter(s);
        if (!chosen.empty()) {
            const double pooled = (r.weights.count("gaussian") ? r.weights.at("gaussian") : 0.0) +
                                  (r.weights.count("sat") ? r.weights.at("sat") : 0.0);
            r.weights[chosen] = pooled;
            r.weights[chosen == "gaussian" ? "sat" : "gaussian"] = 0.0;
        }
    } else {
        s.notes.push_back("filters: both (rubric): gaussian and sat each graded on the scenes "
                          "that use them");
    }
    std::vector<std::string> present;
    for (const auto& stage : stageNames())
        if (std::any_of(s.tests.begin(), s.tests.end(), [&](const TestResult& t) { return t.stage == stage; }))
            present.push_back(stage);
    const auto stagePoints = r.stageHundredths(present);
    long score = 0, max = 0;
    bool rescaled = false;
    std::string perStage;
    for (const auto& stage : present) {
        const long h = stagePoints.at(stage);
        const double weight = r.weights.count(stage) ? r.weights.at(stage) : 0.0;
        if (h != std::lround(weight * 100.0)) rescaled = true;
        perStage += (perStage.empty() ? "" : ", ") + stage + " " + hundredthsText(h);
        int n = 0;
        for (const auto& t : s.tests) n += t.stage == stage;
        const std::vector<long> parts = splitHundredths(h, n);
        size_t k = 0;
        for (auto& t : s.tests) {
            if (t.stage != stage) continue;
            const long m = parts[k++];
            const long e = earnedHundredths(t.fraction, m);
            t.maxScore = double(m) / 100.0;
            t.score = double(e) / 100.0;
            score += e;
            max += m;
        }
    }
    s.score = double(score) / 100.0;
    s.maxScore = double(max) / 100.0;
    if (rescaled)
        s.notes.push_back("points per stage (weights rescaled to the total " +
                          hundredthsText(std::lround(r.total * 100.0)) + "): " + perStage);
}

}  // namespace sl::grader
