// study_figures: see study_figures.h.
#include "study_figures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

namespace sl {

double markerSize(int mapSize) {
    return 0.6 + 0.35 * std::max(0.0, std::log2(double(mapSize) / 256.0));
}

std::string kernelColour(const std::string& filter, int radius) {
    if (filter == "none" || radius <= 0) return "#000000";
    // Five steps per filter, r = 1, 2, 4, 8, 16 (others take the nearest).
    static const char* blue[] = {"#9ecae1", "#6baed6", "#3182bd", "#08519c", "#08306b"};
    static const char* orange[] = {"#fdae6b", "#fd8d3c", "#e6550d", "#a63603", "#7f2704"};
    const int step = std::clamp(int(std::lround(std::log2(double(radius)))), 0, 4);
    return filter == "sat" ? orange[step] : blue[step];
}

std::string kernelName(const std::string& filter, int radius) {
    return filter == "none" || radius <= 0 ? "none" : filter + " r" + std::to_string(radius);
}

PassGroups passGroups(const StudyRow& row) {
    PassGroups g;
    std::istringstream in(row.passTimes);
    for (std::string item; std::getline(in, item, ';');) {
        const size_t eq = item.find('=');
        if (eq == std::string::npos) continue;
        std::string name = item.substr(0, eq);
        name = name.substr(0, name.find('@'));
        // min/median/max: the median.
        const std::string values = item.substr(eq + 1);
        const size_t a = values.find('/');
        const double median = a == std::string::npos ? 0 : std::atof(values.c_str() + a + 1);
        if (name == "shadow" || name == "shadow-second") g.shadow += median;
        else if (name == "lighting") g.lighting += median;
        else g.filter += median;  // widen, gaussian-x/y, sat-rows/columns/resolve
    }
    return g;
}

int figureMapSize(const std::vector<const StudyRow*>& rows) {
    int largest = 0;
    for (const StudyRow* r : rows) {
        if (r->mapSize == 1024) return 1024;
        largest = std::max(largest, r->mapSize);
    }
    return largest;
}

std::string writeKernelAndPassData(const fs::path& plots, const std::vector<const StudyRow*>& rows) {
    const int size = figureMapSize(rows);
    // Per (spec, filter) with more than one radius: cost against the radius.
    std::vector<std::string> order;
    std::map<std::string, std::vector<const StudyRow*>> series;
    std::map<std::string, std::vector<const StudyRow*>> bySpec;
    std::vector<std::string> specs;
    for (const StudyRow* r : rows) {
        if (r->mapSize != size) continue;
        if (!bySpec.count(r->spec)) specs.push_back(r->spec);
        bySpec[r->spec].push_back(r);
        if (r->filter == "none") continue;
        const std::string key = r->spec + " " + r->filter;
        if (!series.count(key)) order.push_back(key);
        series[key].push_back(r);
    }
    std::string names;
    int n = 0;
    for (const std::string& key : order) {
        auto& rs = series[key];
        if (rs.size() < 2) continue;  // a kernel the technique picks per pixel: one row
        std::sort(rs.begin(), rs.end(), [](auto a, auto b) { return a->radius < b->radius; });
        std::ofstream out(plots / ("kernel_" + std::to_string(++n) + ".dat"));
        out << "# radius frame/copy filter/copy lighting/copy kernel_texels\n";
        for (const StudyRow* r : rs) {
            const PassGroups g = passGroups(*r);
            const double copy = r->copyMillis > 0 ? r->copyMillis : 1;
            out << r->radius << " " << formatNumber(r->frameRatio) << " " << formatNumber(g.filter / copy) << " "
                << formatNumber(g.lighting / copy) << " " << formatNumber(r->kernelTexels) << "\n";
        }
        std::string name = key;
        std::replace(name.begin(), name.end(), ' ', ':');  // one word per series
        names += (names.empty() ? "" : " ") + name;
    }
    // Per technique: its cheapest-kernel configuration (Gaussian where it has one).
    std::ofstream bars(plots / "passes.dat");
    bars << "# technique shadow/copy filter/copy lighting/copy\n";
    for (const std::string& spec : specs) {
        const auto& rs = bySpec[spec];
        const StudyRow* pick = nullptr;
        for (const StudyRow* r : rs) {
            auto rank = [](const StudyRow* x) { return (x->filter == "gaussian" ? 0 : x->filter == "none" ? 1 : 2) * 1000 + x->radius; };
            if (!pick || rank(r) < rank(pick)) pick = r;
        }
        const PassGroups g = passGroups(*pick);
        const double copy = pick->copyMillis > 0 ? pick->copyMillis : 1;
        bars << "\"" << spec << " " << kernelName(pick->filter, pick->radius) << "\" "
             << formatNumber(g.shadow / copy) << " " << formatNumber(g.filter / copy) << " " << formatNumber(g.lighting / copy)
             << "\n";
    }
    return "kseries='" + names + "'; kmap=" + std::to_string(size);
}

std::string writeFlickerData(const fs::path& plots, const std::vector<const StudyRow*>& rows) {
    std::vector<std::string> specs;
    // Per spec and map size: the row with the cheapest kernel (Gaussian first, smallest r).
    std::map<std::string, std::map<int, const StudyRow*>> pick;
    auto rank = [](const StudyRow* x) {
        return (x->filter == "gaussian" ? 0 : x->filter == "none" ? 1 : 2) * 1000 + x->radius;
    };
    for (const StudyRow* r : rows) {
        if (r->flickerFrames < 2) continue;
        if (!pick.count(r->spec)) specs.push_back(r->spec);
        const StudyRow*& p = pick[r->spec][r->mapSize];
        if (!p || rank(r) < rank(p)) p = r;
    }
    if (specs.empty()) return "";
    std::string names;
    int n = 0;
    for (const std::string& spec : specs) {
        std::ofstream out(plots / ("flicker_" + std::to_string(++n) + ".dat"));
        out << "# map_size flicker truth_change kernel\n";
        for (const auto& [size, r] : pick[spec])
            out << size << " " << formatNumber(r->flicker) << " " << formatNumber(r->flickerTruth) << " \""
                << kernelName(r->filter, r->radius) << "\"\n";
        names += (names.empty() ? "" : " ") + spec;
    }
    return "fseries='" + names + "'";
}

}  // namespace sl
