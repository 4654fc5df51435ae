// study_pick: see study_pick.h.
#include "study_pick.h"

#include "study_figures.h"

#include <cstdio>

namespace sl {
namespace {

// The row minimising `key` among those within `slack` of the lowest RMSE (ties: lower RMSE).
template <class Key>
const StudyRow* cheapestWithin(const std::vector<const StudyRow*>& rows, double bestRmse,
                               double slack, Key key) {
    const StudyRow* pick = nullptr;
    for (const StudyRow* r : rows) {
        if (r->truth.rmse > bestRmse * (1.0 + slack)) continue;
        if (!pick || key(r) < key(pick) || (key(r) == key(pick) && r->truth.rmse < pick->truth.rmse))
            pick = r;
    }
    return pick;
}

}  // namespace

std::vector<Pick> pickConfigurations(const std::vector<const StudyRow*>& rows) {
    std::vector<Pick> out;
    if (rows.empty()) return out;
    const StudyRow* best = rows.front();
    for (const StudyRow* r : rows)
        if (r->truth.rmse < best->truth.rmse) best = r;
    const double e = best->truth.rmse;
    auto cost = [](const StudyRow* r) { return r->frameRatio; };
    auto bytes = [](const StudyRow* r) { return double(r->mapBytes); };
    out.push_back({"most accurate", best});
    out.push_back({"cheapest frame within 10 % of that error", cheapestWithin(rows, e, 0.10, cost)});
    out.push_back({"cheapest frame within 50 %", cheapestWithin(rows, e, 0.50, cost)});
    out.push_back({"fewest map bytes within 10 %", cheapestWithin(rows, e, 0.10, bytes)});
    return out;
}

std::string pickConfiguration(const StudyRow& r) {
    return r.spec + " " + kernelName(r.filter, r.radius) + " " + std::to_string(r.mapSize) + "²";
}

std::string pickMarkdownHeader() {
    return "| scene | light | question | configuration | RMSE (truth) | frame/copy | map bytes |\n"
           "|---|---|---|---|---|---|---|\n";
}

std::string pickMarkdown(const std::vector<Pick>& picks) {
    std::string s;
    for (const Pick& p : picks) {
        const StudyRow& r = *p.row;
        s += "| " + r.scene + " | " + (r.lightSize > 0 ? formatNumber(r.lightSize, "%g disk") : "point") +
             " | " + p.question + " | " + pickConfiguration(r) + " | " + formatNumber(r.truth.rmse, "%.4f") +
             " | " + formatNumber(r.frameRatio, "%.2f") + " | " + std::to_string(r.mapBytes) + " |\n";
    }
    return s;
}

}  // namespace sl
