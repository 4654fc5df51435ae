// gradebook: scores.csv, the index of reports and the class page, from the batch's rows.
#include "gradebook.h"

#include "html_escape.h"
#include "out_guard.h"
#include "results.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstdio>
#include <sstream>

namespace sl::grader {
namespace {

std::string csvField(std::string s) {
    for (char& c : s) if (c == '\n' || c == '\r') c = ' ';
    if (s.find_first_of(",\"") == std::string::npos) return s;
    std::string o = "\"";
    for (char c : s) o += c == '"' ? std::string("\"\"") : std::string(1, c);
    return o + "\"";
}

std::string joined(const std::vector<std::string>& parts) {
    std::string s;
    for (const auto& p : parts) s += (s.empty() ? "" : "; ") + p;
    return s;
}

// A folder name as one URL path segment.
std::string urlSegment(const std::string& s) {
    std::string o;
    for (unsigned char c : s) {
        if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~') {
            o += char(c);
        } else {
            char buf[4];
            std::snprintf(buf, sizeof buf, "%%%02X", c);
            o += buf;
        }
    }
    return o;
}

// The stages any graded row is worth points on, in report order.
std::vector<std::string> gradedStages(const std::vector<GradebookEntry>& entries) {
    std::vector<std::string> out;
    for (const auto& stage : stageNames())
        for (const auto& e : entries)
            if (e.row && !e.row->failed && e.row->stageMax.count(stage) && e.row->stageMax.at(stage) > 0) {
                out.push_back(stage);
                break;
            }
    return out;
}

const char* kStyle =
    "<style>body{font-family:sans-serif;margin:2em;background:#fafafa;color:#222}"
    "table{border-collapse:collapse;margin:0.5em 0}td,th{border:1px solid #ccc;padding:4px 8px;"
    "text-align:left;vertical-align:top}.full{background:#e6f4e6}.lost{background:#fbe3e3}"
    ".missing{background:#eee;color:#666}.charts{display:flex;flex-wrap:wrap;gap:16px}"
    "figure{margin:0}figcaption{font-weight:bold}</style>";

// A histogram of fractions of the maximum: 0–9 %, …, 90–99 % and exactly 100 % (eleven bars).
std::string histogram(const std::vector<double>& fractions) {
    std::vector<int> bins(11, 0);
    for (double f : fractions) {
        const int b = f >= 1.0 - 1e-9 ? 10 : std::clamp(int(f * 10.0), 0, 9);
        ++bins[size_t(b)];
    }
    const int most = std::max(1, *std::max_element(bins.begin(), bins.end()));
    const int w = 24, gap = 4, h = 120, top = 16, bottom = 34;
    std::ostringstream s;
    const int width = 11 * (w + gap) + gap;
    s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << top + h + bottom
      << "\" role=\"img\"><rect width=\"100%\" height=\"100%\" fill=\"#fff\" stroke=\"#ccc\"/>";
    for (int b = 0; b < 11; ++b) {
        const int bar = bins[size_t(b)] * h / most;
        const int x = gap + b * (w + gap);
        s << "<rect x=\"" << x << "\" y=\"" << top + h - bar << "\" width=\"" << w << "\" height=\"" << bar
          << "\" fill=\"" << (b == 10 ? "#4a9d4a" : "#c0504d") << "\"/>";
        if (bins[size_t(b)])
            s << "<text x=\"" << x + w / 2 << "\" y=\"" << top + h - bar - 3 << "\" font-size=\"11\" "
              << "text-anchor=\"middle\">" << bins[size_t(b)] << "</text>";
        s << "<text x=\"" << x + w / 2 << "\" y=\"" << top + h + 14 << "\" font-size=\"10\" "
          << "text-anchor=\"middle\">" << (b == 10 ? "100" : std::to_string(b * 10)) << "</text>";
    }
    s << "<text x=\"" << width / 2 << "\" y=\"" << top + h + 29 << "\" font-size=\"10\" "
      << "text-anchor=\"middle\">% of the points (bar 0: 0–9 %)</text></svg>";
    return s.str();
}

}  // namespace

std::string scoresCsv(const std::vector<GradebookEntry>& entries) {
    std::ostringstream csv;
    csv << "student,total,max";
    for (const auto& stage : stageNames()) csv << "," << stage;
    csv << ",lost,notes\n";
    for (const auto& e : entries) {
        csv << csvField(e.name);
        if (!e.row) {
            csv << ",," << std::string(stageNames().size(), ',') << ",,not graded\n";  // total, max, stages, lost
            continue;
        }
        const BatchRow& r = *e.row;
        csv << "," << fixedDigits(r.score) << "," << fixedDigits(r.maxScore);
        for (const auto& stage : stageNames()) {
            auto it = r.stagePoints.find(stage);
            csv << "," << (it == r.stagePoints.end() ? "" : fixedDigits(it->second));
        }
        csv << "," << csvField(joined(r.lost)) << "," << csvField(joined(r.notes)) << "\n";
    }
    return csv.str();
}

std::string indexPage(const std::vector<GradebookEntry>& entries) {
    const auto stages = gradedStages(entries);
    std::ostringstream h;
    h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Shadowlab: every "
         "student</title>" << kStyle << "</head><body>\n<h1>Every student (" << entries.size()
      << ")</h1>\n<p><a href=\"class.html\">The class at a glance</a> &middot; <a href=\"scores.csv\">"
         "scores.csv</a></p>\n<table><tr><th>student</th><th>total</th>";
    for (const auto& stage : stages) h << "<th>" << stage << "</th>";
    h << "<th>lost on</th><th>notes</th></tr>\n";
    for (const auto& e : entries) {
        const std::string dir = urlSegment(e.name);
        if (!e.row) {
            h << "<tr class=\"missing\"><td>" << htmlEscape(e.name) << "</td><td colspan=\""
              << stages.size() + 3 << "\">not graded</td></tr>\n";
            continue;
        }
        const BatchRow& r = *e.row;
        const bool full = !r.failed && r.score >= r.maxScore - 1e-9;
        h << "<tr class=\"" << (full ? "full" : "lost") << "\"><td>"
          << (r.report ? "<a href=\"" + dir + "/report/index.html\">" + htmlEscape(e.name) + "</a>"
                       : htmlEscape(e.name))
          << " <small>(<a href=\"" << dir << "/results.json\">results.json</a>)</small></td><td>"
          << fixedDigits(r.score) << " / " << fixedDigits(r.maxScore) << "</td>";
        for (const auto& stage : stages) {
            auto got = r.stagePoints.find(stage);
            auto of = r.stageMax.find(stage);
            h << "<td>" << (got == r.stagePoints.end() ? "" : fixedDigits(got->second))
              << (of == r.stageMax.end() ? "" : " / " + fixedDigits(of->second)) << "</td>";
        }
        h << "<td>" << htmlEscape(joined(r.lost)) << "</td><td>" << htmlEscape(joined(r.notes)) << "</td></tr>\n";
    }
    h << "</table>\n</body></html>\n";
    return h.str();
}

std::string classPage(const std::vector<GradebookEntry>& entries) {
    std::vector<const BatchRow*> graded;
    size_t failed = 0, missing = 0;
    for (const auto& e : entries) {
        if (!e.row) ++missing;
        else if (e.row->failed) ++failed;
        else graded.push_back(&*e.row);
    }
    std::ostringstream h;
    h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Shadowlab: the "
         "class</title>" << kStyle << "</head><body>\n<h1>The class at a glance</h1>\n<p>"
      << entries.size() << " submissions: " << graded.size() << " graded, " << failed
      << " the grader could not grade, " << missing << " not graded yet. <a href=\"index.html\">Every "
         "student</a> &middot; <a href=\"scores.csv\">scores.csv</a></p>\n<div class=\"charts\">\n";
    auto chart = [&](const std::string& title, auto fraction) {
        std::vector<double> f;
        for (const BatchRow* r : graded) {
            const double v = fraction(*r);
            if (v >= 0) f.push_back(v);
        }
        h << "<figure><figcaption>" << htmlEscape(title) << " (" << f.size() << ")</figcaption>"
          << histogram(f) << "</figure>\n";
    };
    chart("total", [](const BatchRow& r) { return r.maxScore > 0 ? r.score / r.maxScore : -1.0; });
    for (const auto& stage : gradedStages(entries))
        chart(stage, [&stage](const BatchRow& r) {
            auto of = r.stageMax.find(stage);
            auto got = r.stagePoints.find(stage);
            if (of == r.stageMax.end() || of->second <= 0 || got == r.stagePoints.end()) return -1.0;
            return got->second / of->second;
        });
    h << "</div>\n";

    // The tests most often lost: "scene stage", how many lost points on it, the mean loss.
    struct Lost { int students = 0; double points = 0; };
    std::map<std::string, Lost> lost;
    for (const BatchRow* r : graded)
        for (const auto& l : r->lost) {
            const size_t cut = l.rfind(" -");
            Lost& x = lost[l.substr(0, cut)];
            ++x.students;
            if (cut != std::string::npos) x.points += std::atof(l.c_str() + cut + 2);
        }
    std::vector<std::pair<std::string, Lost>> order(lost.begin(), lost.end());
    std::stable_sort(order.begin(), order.end(),
                     [](const auto& a, const auto& b) { return a.second.students > b.second.students; });
    h << "<h2>The tests most often lost</h2>\n";
    if (order.empty()) h << "<p>No graded submission lost a point.</p>\n";
    else h << "<table><tr><th>scene and stage</th><th>students</th><th>mean points lost</th></tr>\n";
    for (size_t i = 0; i < order.size() && i < 20; ++i)
        h << "<tr><td>" << htmlEscape(order[i].first) << "</td><td>" << order[i].second.students << "</td><td>"
          << fixedDigits(order[i].second.points / order[i].second.students) << "</td></tr>\n";
    if (!order.empty()) h << "</table>\n";
    h << "</body></html>\n";
    return h.str();
}

void writeGradebook(const fs::path& out, const std::vector<GradebookEntry>& entries) {
    writeFileSafely(out / "scores.csv", scoresCsv(entries));
    writeFileSafely(out / "index.html", indexPage(entries));
    writeFileSafely(out / "class.html", classPage(entries));
}

}  // namespace sl::grader
