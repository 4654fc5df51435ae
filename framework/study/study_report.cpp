// study_report: plots and page of a study (see study_report.h).
#include "study_report.h"

#include "html_escape.h"
#include "paths.h"
#include "study_crops.h"
#include "study_figures.h"
#include "study_pick.h"

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

// The report's tables: four significant digits.
constexpr const char* kTableDigits = "%.4g";

std::string label(const StudyRow& r) {
    return r.filter + (r.radius ? " r" + std::to_string(r.radius) : "") + " " +
           std::to_string(r.mapSize);
}

// gnuplot's log axes cannot show 0: an exact row is drawn at the axis floor.
double plotY(double v) { return std::max(v, 1e-5); }

void writeDat(const fs::path& p, const std::vector<const StudyRow*>& rows) {
    std::ofstream out(p);
    out << "# frame_over_copy truth_rmse map_bytes marker_size colour label\n";
    for (const StudyRow* r : rows)
        out << formatNumber(r->frameRatio, "%.6g") << " " << formatNumber(plotY(r->truth.rmse), "%.6g") << " "
            << r->mapBytes << " " << formatNumber(markerSize(r->mapSize), "%.3f") << " "
            << std::stol(kernelColour(r->filter, r->radius).substr(1), nullptr, 16) << " \""
            << label(*r) << "\"\n";
}

std::string slugOf(const std::string& s) {
    std::string o;
    for (char c : s) o += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' ? c : '_';
    return o;
}

void runGnuplot(const std::string& vars, const std::string& script, const fs::path& logFile) {
    const std::string cmd = "gnuplot -e \"" + vars + "\" '" + (repoRoot() / "tools" / script).string() +
                            "' > '" + logFile.string() + "' 2>&1";
    // gnuplot's warnings (a one-point series has an "empty range") go to the log.
    if (std::system(cmd.c_str()) != 0)
        throw std::runtime_error("gnuplot failed (" + cmd + "; see " + logFile.string() +
                                 "); is gnuplot-nox installed?");
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
// The row of `rows` under light size `lightSize` closest to the truth (RMSE), or null.
const StudyRow* mostAccurate(const std::vector<const StudyRow*>& rows, double lightSize) {
    const StudyRow* best = nullptr;
    for (const StudyRow* r : rows)
        if (r->lightSize == lightSize && (!best || r->truth.rmse < best->truth.rmse)) best = r;
    return best;
}

std::string truthImage(const fs::path& dir, double lightSize) {
    const std::string own = "truth/light_" + formatNumber(lightSize, "%g") + "/truth.png";
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
        std::vector<Pick> picks;
        std::string costName;  // kernel_cost / pass_cost files' suffix
        bool flicker = false;  // rows measured flicker: flicker<costName>.svg
    };
    std::vector<PlotSet> sets;
    std::vector<std::string> specs;
    std::map<std::string, std::vector<const StudyRow*>> bySpec;
    for (const StudyRow& r : rows) {
        if (!bySpec.count(r.spec)) specs.push_back(r.spec);
        bySpec[r.spec].push_back(&r);
    }
    for (double lightSize : lightSizes) {
        PlotSet set{lightSize, sets.empty() ? "pareto" : "pareto_light_" + formatNumber(lightSize, "%g"), {}, {}, {}, false};
        const fs::path plots = dir / (sets.empty() ? "plots" : "plots_light_" + formatNumber(lightSize, "%g"));
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
        const std::string setTitle = title + (lightSizes.size() > 1 || lightSize > 0
                                                  ? ", light size " + formatNumber(lightSize, "%g")
                                                  : "");
        // The legend's map sizes and kernels, and a y range fitted to the data.
        std::vector<int> sizes;
        std::vector<std::pair<std::string, int>> kernels;
        double ymin = 1e300, ymax = 0;
        for (const StudyRow* r : all) {
            if (std::find(sizes.begin(), sizes.end(), r->mapSize) == sizes.end()) sizes.push_back(r->mapSize);
            const std::pair<std::string, int> k{r->filter == "none" ? "none" : r->filter,
                                                r->filter == "none" ? 0 : r->radius};
            if (std::find(kernels.begin(), kernels.end(), k) == kernels.end()) kernels.push_back(k);
            ymin = std::min(ymin, plotY(r->truth.rmse));
            ymax = std::max(ymax, plotY(r->truth.rmse));
        }
        std::sort(sizes.begin(), sizes.end());
        std::sort(kernels.begin(), kernels.end());
        std::string sizeWords, kernelWords, colourWords;
        for (int z : sizes) sizeWords += (sizeWords.empty() ? "" : " ") + std::to_string(z);
        for (const auto& [f, r] : kernels) {
            std::string k = kernelName(f, r);
            std::replace(k.begin(), k.end(), ' ', ':');
            kernelWords += (kernelWords.empty() ? "" : " ") + k;
            colourWords += (colourWords.empty() ? "" : " ") + kernelColour(f, r);
        }
        runGnuplot("dir='" + plots.string() + "'; out='" + (dir / set.name).string() + "'; names='" +
                       names + "'; title='" + setTitle + "'; sizes='" + sizeWords + "'; kernels='" +
                       kernelWords + "'; kcolours='" + colourWords + "'; ymin=" +
                       formatNumber(ymin / 1.12, "%.6g") + "; ymax=" + formatNumber(ymax * 1.12, "%.6g"),
                   "study_plots.gp", plots / "gnuplot.log");
        log << "wrote " << (dir / set.name).string() << ".{svg,png}, " << set.name << "_bytes.{svg,png}\n";
        // Cost against kernel radius and per pass (study_figures.h).
        set.costName = sets.empty() ? "" : "_light_" + formatNumber(lightSize, "%g");
        const std::string kvars = writeKernelAndPassData(plots, all);
        runGnuplot(kvars + "; dir='" + plots.string() + "'; out='" +
                       (dir / ("kernel_cost" + set.costName)).string() + "'; bars='" +
                       (dir / ("pass_cost" + set.costName)).string() + "'; title='" + setTitle + "'",
                   "study_cost_plots.gp", plots / "gnuplot_cost.log");
        set.picks = pickConfigurations(all);
        const std::string fvars = writeFlickerData(plots, all);
        set.flicker = !fvars.empty();
        if (set.flicker)
            runGnuplot(fvars + "; dir='" + plots.string() + "'; out='" +
                           (dir / ("flicker" + set.costName)).string() + "'; title='" + setTitle + "'",
                       "study_flicker.gp", plots / "gnuplot_flicker.log");
        sets.push_back(std::move(set));
    }

    std::ofstream page(dir / "index.html");
    page << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>Shadowlab study: "
         << htmlEscape(title) << "</title>\n<style>body{font-family:sans-serif;margin:2em;max-width:1400px}"
            "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #ccc;padding:3px 8px;"
            "text-align:right}th{background:#eee}td.l{text-align:left}figure{display:inline-block;"
            "margin:4px}figure img{width:256px;image-rendering:pixelated}figcaption{font-size:80%}"
            "</style></head><body>\n<h1>Accuracy against cost: " << htmlEscape(title) << "</h1>\n";
    if (!headline.empty()) page << "<p>" << htmlEscape(headline) << "</p>\n";
    page << "<p>Error: G against the ray-traced truth over the pixels the light reaches. Cost: the "
            "frame's CPU time across llvmpipe's threads (" << htmlEscape(rows.front().costMethod)
         << "), minimum over repeats, divided by a 1024² RGBA32F copy pass's, measured the same "
            "way and interleaved with the frames. "
            "Every figure here is drawn from <a href=\"study.csv\">study.csv</a>.</p>\n"
            ;
    for (const PlotSet& set : sets) {
        page << "<h2>Light size " << formatNumber(set.lightSize, "%g")
             << (set.lightSize > 0 ? " (area light: soft truth)" : " (point light: hard truth)")
             << "</h2>\n<img src=\"" << set.name << ".svg\" alt=\"error against cost\" width=\"900\">\n"
             << "<img src=\"" << set.name << "_bytes.svg\" alt=\"error against map bytes\" width=\"900\">\n"
                "<h3>Pareto-optimal configurations (error against cost)</h3>\n<table><tr><th>technique"
                "</th><th>filter</th><th>r</th><th>map</th><th>bytes</th><th>frame/copy</th>"
                "<th>RMSE truth</th><th>p99 truth</th><th>RMSE filtered</th><th>leak area</th></tr>\n";
        for (const StudyRow* r : set.timeFront)
            page << "<tr><td class=l>" << htmlEscape(r->spec) << "</td><td class=l>" << r->filter << "</td><td>"
                 << r->radius << "</td><td>" << r->mapSize << "²</td><td>" << r->mapBytes << "</td><td>"
                 << formatNumber(r->frameRatio, "%.2f") << "</td><td>" << formatNumber(r->truth.rmse, kTableDigits) << "</td><td>"
                 << formatNumber(r->truth.p99, kTableDigits) << "</td><td>" << formatNumber(r->filtered.rmse, kTableDigits) << "</td><td>"
                 << formatNumber(r->truth.leakArea, kTableDigits) << "</td></tr>\n";
        page << "</table>\n<h3>Which configuration to pick (from the table above)</h3>\n<table><tr>"
                "<th>question</th><th>configuration</th><th>RMSE truth</th><th>frame/copy</th>"
                "<th>map bytes</th></tr>\n";
        for (const Pick& p : set.picks)
            page << "<tr><td class=l>" << htmlEscape(p.question) << "</td><td class=l>"
                 << htmlEscape(pickConfiguration(*p.row)) << "</td><td>" << formatNumber(p.row->truth.rmse, kTableDigits)
                 << "</td><td>" << formatNumber(p.row->frameRatio, "%.2f") << "</td><td>" << p.row->mapBytes
                 << "</td></tr>\n";
        page << "</table>\n<h3>Where the cost goes</h3>\n<img src=\"kernel_cost" << set.costName
             << ".svg\" alt=\"cost against kernel radius\" width=\"900\">\n<img src=\"pass_cost"
             << set.costName << ".svg\" alt=\"cost per pass\" width=\"900\">\n";
        if (set.flicker)
            page << "<h3>Temporal stability</h3>\n<p>The light turns a little each frame "
                    "(<code>--flicker</code>); flicker is the mean frame-to-frame change of G "
                    "minus the ray-traced truth's own change, over the pixels the light reaches "
                    "(0: as steady as the truth; below 0: the blur hides real motion).</p>\n"
                    "<img src=\"flicker" << set.costName << ".svg\" alt=\"flicker\" width=\"900\">\n";
    }
    {
        std::ofstream pick(dir / "pick.md");
        for (const PlotSet& set : sets) pick << pickMarkdown(set.picks);
    }
    page << "<h2>Failures, enlarged: G | truth | error, per technique's most accurate "
            "configuration</h2>\n<p>The window where it leaks most (G below the truth by more "
            "than 0.1: light where the truth has shadow) and where it over-darkens most (acne, "
            "a filter's bias, a moment bound).</p>\n";
    for (double lightSize : lightSizes)
    for (const std::string& spec : specs) {
        const StudyRow* best = mostAccurate(bySpec[spec], lightSize);
        if (!best) continue;
        const auto crops = writeFailureCrops(dir, *best, truthImage(dir, lightSize),
                                             slugOf(spec) + "_light" + formatNumber(lightSize, "%g"));
        for (const FailureCrop& c : crops)
            page << "<figure><img style=\"width:auto\" src=\"" << c.file << "\" alt=\"" << c.kind
                 << "\"><figcaption>" << htmlEscape(spec) << ", " << htmlEscape(label(*best)) << ", light "
                 << formatNumber(lightSize, "%g") << ": " << (c.kind == "leak" ? "light leaking" : "too dark")
                 << ", mean |ΔG| " << formatNumber(c.meanError, "%.2f") << " at (" << c.x << ", " << c.y
                 << ")</figcaption></figure>\n";
    }
    page << "<h2>Per technique: its most accurate configuration</h2>\n";
    for (double lightSize : lightSizes)
    for (const std::string& spec : specs) {
        const StudyRow* best = mostAccurate(bySpec[spec], lightSize);
        if (!best) continue;
        page << "<h3>" << htmlEscape(spec) << " — " << htmlEscape(label(*best)) << ", light size "
             << formatNumber(lightSize, "%g") << ": RMSE "
             << formatNumber(best->truth.rmse, kTableDigits) << " (truth), " << formatNumber(best->filtered.rmse, kTableDigits)
             << " (filtered truth), frame/copy " << formatNumber(best->frameRatio, "%.2f") << "</h3>\n"
             << "<figure><img src=\"" << best->image << "\" alt=\"G\"><figcaption>G, " << htmlEscape(spec)
             << "</figcaption></figure><figure><img src=\"" << best->errorMap
             << "\" alt=\"error\"><figcaption>G − truth (red: leaks, blue: too dark)</figcaption>"
                "</figure><figure><img src=\"" << truthImage(dir, best->lightSize)
             << "\" alt=\"truth\"><figcaption>ray-traced truth</figcaption></figure>\n";
    }
    page << "<h2>All rows</h2>\n<table><tr><th>technique</th><th>filter</th><th>r</th><th>map</th>"
            "<th>light</th><th>frame CPU ms (min / median / max)</th><th>frame/copy</th><th>RMSE truth</th><th>max</th><th>RMSE filtered"
            "</th><th>reused</th></tr>\n";
    for (const StudyRow& r : rows)
        page << "<tr><td class=l>" << htmlEscape(r.spec) << "</td><td class=l>" << r.filter << "</td><td>"
             << r.radius << "</td><td>" << r.mapSize << "²</td><td>" << formatNumber(r.lightSize, "%g")
             << "</td><td>" << formatNumber(r.frameMin, "%.2f") << " / " << formatNumber(r.frameMedian, "%.2f")
             << " / " << formatNumber(r.frameMax, "%.2f") << "</td><td>" << formatNumber(r.frameRatio, "%.2f") << "</td><td>" << formatNumber(r.truth.rmse, kTableDigits)
             << "</td><td>" << formatNumber(r.truth.max, kTableDigits) << "</td><td>" << formatNumber(r.filtered.rmse, kTableDigits)
             << "</td><td class=l>" << htmlEscape(r.reused) << "</td></tr>\n";
    page << "</table>\n</body></html>\n";
    log << "wrote " << (dir / "index.html").string() << "\n";
}

}  // namespace sl
