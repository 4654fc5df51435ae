// report: one page per grade with, for every scene and stage, the reference, the student's
// image, a heat-map of the error in units of the tolerance, and the metrics. Everything it
// shows is copied into the folder (no links out), so it can be zipped or served as is.
// Images wider than kMaxPreview are shown reduced: the heat-map keeps each block's worst
// error, so a single wrong texel stays visible.
#include "report.h"

#include "image_io.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace sl::grader {
namespace {

constexpr int kMaxPreview = 512;

int stepFor(const Image& img) { return std::max(1, (std::max(img.width, img.height) + kMaxPreview - 1) / kMaxPreview); }

// Every step-th texel (values), or the block maximum (error maps).
Image reduce(const Image& img, int step, bool blockMax) {
    if (step == 1) return img;
    Image out(img.width / step, img.height / step, img.channels);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x)
            for (int c = 0; c < img.channels; ++c) {
                float v = img.at(x * step, y * step, c);
                if (blockMax)
                    for (int dy = 0; dy < step; ++dy)
                        for (int dx = 0; dx < step; ++dx)
                            v = std::max(v, img.at(x * step + dx, y * step + dy, c));
                out.at(x, y, c) = v;
            }
    return out;
}

// error/tolerance -> colour: black (exact), blue to cyan (within tolerance), yellow to red.
Image heatMap(const Image& err) {
    Image out(err.width, err.height, 3);
    for (size_t i = 0; i < size_t(err.width) * err.height; ++i) {
        const float e = err.pixels[i];
        float r, g, b;
        if (e <= 1.0f) {
            const float t = std::sqrt(std::max(0.0f, e));
            r = 0.0f, g = 0.6f * t, b = t;
        } else {
            const float t = std::min(1.0f, std::log10(e) / 3.0f);  // 1× .. 1000× the tolerance
            r = 1.0f, g = 1.0f - t, b = 0.0f;
        }
        out.pixels[i * 3] = r, out.pixels[i * 3 + 1] = g, out.pixels[i * 3 + 2] = b;
    }
    return out;
}

std::string escape(const std::string& s) {
    std::string o;
    for (char c : s) {
        switch (c) {
            case '<': o += "&lt;"; break;
            case '>': o += "&gt;"; break;
            case '&': o += "&amp;"; break;
            case '"': o += "&quot;"; break;
            default: o += c;
        }
    }
    return o;
}

}  // namespace

ReportWriter::ReportWriter(std::filesystem::path dir) : dir_(std::move(dir)) {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
    std::filesystem::create_directories(dir_ / "img");
}

void ReportWriter::add(const TestResult& t, const std::string& image, const Image& ref,
                       const Image& student, const Comparison& c) {
    const std::string base = "img/" + t.scene + "_" + t.stage + "_" + image;
    const bool srgb = image.rfind("final", 0) == 0;
    const int step = stepFor(ref);
    Entry e{t.scene, t.stage, image, base + "_ref.png", base + "_student.png", base + "_diff.png",
            c.toJson()};
    writePngPreview(reduce(ref, step, false), dir_ / e.ref, srgb);
    if (student.width == ref.width && student.height == ref.height)
        writePngPreview(reduce(student, step, false), dir_ / e.student, srgb);
    else
        e.student.clear();
    if (!c.errorMap.empty()) writePngPreview(heatMap(reduce(c.errorMap, step, true)), dir_ / e.diff, false);
    else e.diff.clear();
    entries_.push_back(std::move(e));
}

void ReportWriter::finish(const GradeSummary& s) {
    std::ostringstream h;
    h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
      << "<title>Shadowlab grade report</title><style>"
      << "body{font-family:sans-serif;margin:2em;background:#fafafa;color:#222}"
      << "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:4px 8px;vertical-align:top}"
      << ".passed{background:#e6f4e6}.failed{background:#fbe3e3}pre{white-space:pre-wrap;margin:0;font-size:12px}"
      << ".imgs{display:flex;gap:12px;flex-wrap:wrap}.imgs figure{margin:0}"
      << ".imgs img{width:256px;image-rendering:pixelated;border:1px solid #999;background:#000}"
      << "</style></head><body>\n<h1>Shadowlab grade: " << std::fixed;
    h.precision(2);
    h << s.score << " / " << s.maxScore << "</h1>\n<p>Reference: " << escape(s.referenceMode)
      << ". Heat-maps: black = equal, blue to cyan = within tolerance, yellow to red = outside it "
         "(1× to 1000× the tolerance).</p>\n";
    for (const auto& w : s.warnings) h << "<p><b>warning:</b> " << escape(w) << "</p>\n";
    h << "<table><tr><th>scene</th><th>stage</th><th>points</th><th>output</th></tr>\n";
    for (const auto& t : s.tests) {
        const bool passed = t.score >= t.maxScore - 1e-9;
        h << "<tr class=\"" << (passed ? "passed" : "failed") << "\"><td><a href=\"#" << t.scene
          << "-" << t.stage << "\">" << escape(t.scene) << "</a></td><td>" << t.stage << "</td><td>"
          << t.score << " / " << t.maxScore << "</td><td><pre>" << escape(t.output)
          << "</pre></td></tr>\n";
    }
    h << "</table>\n";
    for (const auto& t : s.tests) {
        h << "<h2 id=\"" << t.scene << "-" << t.stage << "\">" << escape(t.scene) << ": " << t.stage
          << "</h2>\n";
        bool any = false;
        for (const auto& e : entries_) {
            if (e.scene != t.scene || e.stage != t.stage) continue;
            any = true;
            h << "<h3>" << escape(e.image) << "</h3><div class=\"imgs\">";
            auto fig = [&](const std::string& src, const char* caption) {
                if (src.empty()) h << "<figure><figcaption>" << caption << ": none</figcaption></figure>";
                else h << "<figure><img src=\"" << src << "\" alt=\"" << caption << "\"><figcaption>"
                       << caption << "</figcaption></figure>";
            };
            fig(e.ref, "reference");
            fig(e.student, "submission");
            fig(e.diff, "difference");
            h << "</div><pre>" << escape(e.metrics.dump(1)) << "</pre>\n";
        }
        if (!any) h << "<pre>" << escape(t.output) << "</pre>\n";
    }
    h << "</body></html>\n";
    std::ofstream(dir_ / "index.html") << h.str();
}

}  // namespace sl::grader
