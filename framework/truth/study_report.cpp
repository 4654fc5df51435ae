// study_report: plots and page of a study (see study_report.h).
#include "study_report.h"

#include "paths.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <numeric>
#include <ostream>
#include <stdexcept>

namespace sl {
namespace {

std::string num(double v, const char* f = "%.4g") {
    char b[40];
    std::snprintf(b, sizeof b, f, v);
    return b;
}

std::string label(const StudyRow& r) {
    return r.filter + (r.radius ? " r" + std::to_string(r.radius) : "") + " " +
           std::to_string(r.mapSize);
}

std::string html(const std::string& s) {
    std::string o;
    for (char c : s) o += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
    return o;
}

// gnuplot's log axes cannot show 0: an exact row is drawn at the axis floor.
double plotY(double v) { return std::max(v, 1e-5); }

void writeDat(const fs::path& p, const std::vector<const StudyRow*>& rows) {
    std::ofstream out(p);
    out << "# frame_over_copy truth_rmse map_bytes label\n";
    for (const StudyRow* r : rows)
        out << num(r->frameRatio, "%.6g") << " " << num(plotY(r->truth.rmse), "%.6g") << " "
            << r->mapBytes << " \"" << label(*r) << "\"\n";
}

std::vector<const StudyRow*> front(const std::vector<const StudyRow*>& rows, bool bytes) {
    std::vector<double> x, y;
    for (const StudyRow* r : rows) {
        x.push_back(bytes ? double(r->mapBytes) : r->frameRatio);
        y.push_back(plotY(r->truth.rmse));
    }
    std::vector<const StudyRow*> out;
    for (size_t i : paretoFront(x, y)) out.push_back(rows[i]);
    return out;
}

// The truth's preview for a light size: its own folder when the study swept light sizes.
std::string truthImage(const fs::path& dir, double lightSize) {
    const std::string own = "truth/light_" + num(lightSize, "%g") + "/truth.png";
    return fs::exists(dir / own) ? own : "truth/truth.png";
}

}  // namespace

std::vector<size_t> paretoFront(const std::vector<double>& x, const std::vector<double>& y) {
    std::vector<size_t> order(x.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return x[a] != x[b] ? x[a] < x[b] : y[a] < y[b];
    });
    std::vector<size_t> out;
    double best = 1e300;
    for (size_t i : order)
        if (y[i] < best) {
            out.push_back(i);
            best = y[i];
        }
    return out;
}

void writeStudyReport(const fs::path& dir, const std::vector<StudyRow>& rows, std::ostream& log,
                      const std::string& headline) {
    if (rows.empty()) throw std::runtime_error(dir.string() + "/study.csv: no rows to plot");
    // One set of plots per light size: errors against different truths do not share an axis.
    std::vector<double> lightSizes;
    for (const StudyRow& r : rows)
        if (std::find(lightSizes.begin(), lightSizes.end(), r.lightSize) == lightSizes.end())
            lightSizes.push_back(r.lightSize);
    const std::string title = rows.front().scene;
    struct PlotSet {
        double lightSize;
        std::string name;  // "pareto" for the first light size, "pareto_light_0.8" for others
        std::vector<const StudyRow*> timeFront;
    };
    std::vector<PlotSet> sets;
    std::vector<std::string> specs;
    std::map<std::string, std::vector<const StudyRow*>> bySpec;
    for (const StudyRow& r : rows) {
        if (!bySpec.count(r.spec)) specs.push_back(r.spec);
        bySpec[r.spec].push_back(&r);
    }
    for (double lightSize : lightSizes) {
        PlotSet set{lightSize, sets.empty() ? "pareto" : "pareto_light_" + num(lightSize, "%g"), {}};
        const fs::path plots = dir / (sets.empty() ? "plots" : "plots_light_" + num(lightSize, "%g"));
        fs::create_directories(plots);
        std::vector<const StudyRow*> all;
        std::string names;
        int n = 0;
        for (const std::string& spec : specs) {
            std::vector<const StudyRow*> rs;
            for (const StudyRow* r : bySpec[spec])
                if (r->lightSize == lightSize) rs.push_back(r);
            if (rs.empty()) continue;
            all.insert(all.end(), rs.begin(), rs.end());
            ++n;
            writeDat(plots / ("tech_" + std::to_string(n) + ".dat"), rs);
            writeDat(plots / ("techfront_" + std::to_string(n) + ".dat"), front(rs, false));
            writeDat(plots / ("techfront_bytes_" + std::to_string(n) + ".dat"), front(rs, true));
            names += (n > 1 ? " " : "") + spec;
        }
        set.timeFront = front(all, false);
        writeDat(plots / "front.dat", set.timeFront);
        writeDat(plots / "front_bytes.dat", front(all, true));
        const fs::path script = repoRoot() / "tools" / "study_plots.gp";
        const std::string setTitle = title + (lightSizes.size() > 1 || lightSize > 0
                                                  ? ", light size " + num(lightSize, "%g")
                                                  : "");
        const std::string cmd = "gnuplot -e \"dir='" + plots.string() + "'; out='" +
                                (dir / set.name).string() + "'; names='" + names + "'; title='" +
                                setTitle + "'\" '" + script.string() + "' > '" +
                                (plots / "gnuplot.log").string() + "' 2>&1";
        // gnuplot's warnings (a one-point series has an "empty range") go to gnuplot.log.
        if (std::system(cmd.c_str()) != 0)
            throw std::runtime_error("gnuplot failed (" + cmd + "; see gnuplot.log); is "
                                     "gnuplot-nox installed?");
        log << "wrote " << (dir / set.name).string() << ".{svg,png}, " << set.name << "_bytes.{svg,png}\n";
        sets.push_back(std::move(set));
    }

    std::ofstream page(dir / "index.html");
    page << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>Shadowlab study: "
         << html(title) << "</title>\n<style>body{font-family:sans-serif;margin:2em;max-width:1400px}"
            "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #ccc;padding:3px 8px;"
            "text-align:right}th{background:#eee}td.l{text-align:left}figure{display:inline-block;"
            "margin:4px}figure img{width:256px;image-rendering:pixelated}figcaption{font-size:80%}"
            "</style></head><body>\n<h1>Accuracy against cost: " << html(title) << "</h1>\n";
    if (!headline.empty()) page << "<p>" << html(headline) << "</p>\n";
    page << "<p>Error: G against the ray-traced truth over the pixels the light reaches. Cost: the "
            "frame's CPU time across llvmpipe's threads (" << html(rows.front().costMethod)
         << "), minimum over repeats, divided by a 1024² RGBA32F copy pass's, measured the same "
            "way and interleaved with the frames. "
            "Every figure here is drawn from <a href=\"study.csv\">study.csv</a>.</p>\n"
            ;
    for (const PlotSet& set : sets) {
        page << "<h2>Light size " << num(set.lightSize, "%g")
             << (set.lightSize > 0 ? " (area light: soft truth)" : " (point light: hard truth)")
             << "</h2>\n<img src=\"" << set.name << ".svg\" alt=\"error against cost\" width=\"900\">\n"
             << "<img src=\"" << set.name << "_bytes.svg\" alt=\"error against map bytes\" width=\"900\">\n"
                "<h3>Pareto-optimal configurations (error against cost)</h3>\n<table><tr><th>technique"
                "</th><th>filter</th><th>r</th><th>map</th><th>bytes</th><th>frame/copy</th>"
                "<th>RMSE truth</th><th>p99 truth</th><th>RMSE filtered</th><th>leak area</th></tr>\n";
        for (const StudyRow* r : set.timeFront)
            page << "<tr><td class=l>" << html(r->spec) << "</td><td class=l>" << r->filter << "</td><td>"
                 << r->radius << "</td><td>" << r->mapSize << "²</td><td>" << r->mapBytes << "</td><td>"
                 << num(r->frameRatio, "%.2f") << "</td><td>" << num(r->truth.rmse) << "</td><td>"
                 << num(r->truth.p99) << "</td><td>" << num(r->filtered.rmse) << "</td><td>"
                 << num(r->truth.leakArea) << "</td></tr>\n";
        page << "</table>\n";
    }
    page << "<h2>Per technique: its most accurate configuration</h2>\n";
    for (double lightSize : lightSizes)
    for (const std::string& spec : specs) {
        std::vector<const StudyRow*> rs;
        for (const StudyRow* r : bySpec[spec])
            if (r->lightSize == lightSize) rs.push_back(r);
        if (rs.empty()) continue;
        const StudyRow* best = *std::min_element(rs.begin(), rs.end(), [](auto a, auto b) {
            return a->truth.rmse < b->truth.rmse;
        });
        page << "<h3>" << html(spec) << " — " << html(label(*best)) << ", light size "
             << num(lightSize, "%g") << ": RMSE "
             << num(best->truth.rmse) << " (truth), " << num(best->filtered.rmse)
             << " (filtered truth), frame/copy " << num(best->frameRatio, "%.2f") << "</h3>\n"
             << "<figure><img src=\"" << best->image << "\" alt=\"G\"><figcaption>G, " << html(spec)
             << "</figcaption></figure><figure><img src=\"" << best->errorMap
             << "\" alt=\"error\"><figcaption>G − truth (red: leaks, blue: too dark)</figcaption>"
                "</figure><figure><img src=\"" << truthImage(dir, best->lightSize)
             << "\" alt=\"truth\"><figcaption>ray-traced truth</figcaption></figure>\n";
    }
    page << "<h2>All rows</h2>\n<table><tr><th>technique</th><th>filter</th><th>r</th><th>map</th>"
            "<th>light</th><th>frame CPU ms (min / median / max)</th><th>frame/copy</th><th>RMSE truth</th><th>max</th><th>RMSE filtered"
            "</th><th>reused</th></tr>\n";
    for (const StudyRow& r : rows)
        page << "<tr><td class=l>" << html(r.spec) << "</td><td class=l>" << r.filter << "</td><td>"
             << r.radius << "</td><td>" << r.mapSize << "²</td><td>" << num(r.lightSize, "%g")
             << "</td><td>" << num(r.frameMin, "%.2f") << " / " << num(r.frameMedian, "%.2f")
             << " / " << num(r.frameMax, "%.2f") << "</td><td>" << num(r.frameRatio, "%.2f") << "</td><td>" << num(r.truth.rmse)
             << "</td><td>" << num(r.truth.max) << "</td><td>" << num(r.filtered.rmse)
             << "</td><td class=l>" << html(r.reused) << "</td></tr>\n";
    page << "</table>\n</body></html>\n";
    log << "wrote " << (dir / "index.html").string() << "\n";
}

}  // namespace sl
