// report: one page per grade: a per-stage summary, the failure patterns in words
// (report_diagnosis.h), every test with its reason, and, for every scene and stage, the
// reference, the student's image, a heat-map of the error in units of the tolerance, and the
// metrics as tables. Everything it shows is copied into the folder (no links out), so it can
// be zipped or served as is. Images wider than kMaxPreview are shown reduced (the heat-map
// keeps each block's worst error); each preview links its full-size image.
// Hidden scenes never appear in report/ (it may be forwarded to a student); the staff page
// (report-staff/) shows them, marked.
#include "report.h"

#include "html_escape.h"
#include "image_name.h"

#include "image_io.h"
#include "results.h"
#include "sat_kernel_ladder.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
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

}  // namespace

Image previewImage(const Image& image) { return reduce(image, stepFor(image), false); }

namespace {

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



std::string number(const nlohmann::json& j, int digits = 4) {
    if (!j.is_number()) return j.is_null() ? "NaN" : htmlEscape(j.dump());
    std::ostringstream o;
    o.precision(digits);
    o << j.get<double>();
    return o.str();
}

// An anchor id from scene and stage (scene names are file stems; keep ids plain).
std::string anchor(const std::string& scene, const std::string& stage) {
    std::string id = "t-";
    for (char c : scene + "-" + stage) id += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    return id;
}

// The metrics of one compared image as a table row (Comparison::toJson's fields).
void metricsTable(std::ostringstream& h, const nlohmann::json& m) {
    h << "<table class=\"metrics\"><tr><th>within tolerance</th><th>NaN/Inf</th><th>stub texels</th>"
         "<th>worst texel (x, y from bottom-left, channel): value, expected, &times; tolerance</th>"
         "<th>OIIO mean</th><th>RMS</th><th>max</th><th>PSNR</th></tr><tr><td>"
      << fixedDigits(100.0 * m.value("fraction_within_tolerance", 0.0)) << "%</td><td>"
      << m.value("non_finite", 0L) << "</td><td>" << m.value("stub_texels", 0L) << "</td><td>";
    if (m.contains("worst_texel")) {
        const auto& w = m["worst_texel"];
        h << "(" << w.value("x", -1) << ", " << w.value("y", -1) << ", b" << w.value("channel", -1) + 1
          << "): " << number(w["value"], 7) << ", " << number(w["expected"], 7) << ", "
          << number(w["error_over_tolerance"], 3);
    } else {
        h << "&ndash;";
    }
    const auto o = m.value("oiio", nlohmann::json::object());
    h << "</td><td>" << number(o.value("mean", nlohmann::json(0))) << "</td><td>"
      << number(o.value("rms", nlohmann::json(0))) << "</td><td>" << number(o.value("max", nlohmann::json(0)))
      << "</td><td>" << number(o.value("psnr", nlohmann::json(0)), 3) << " dB</td></tr></table>\n";
    if (m.contains("error")) h << "<p>" << htmlEscape(m["error"].get<std::string>()) << "</p>\n";
}

// The hard cases that failed, as a table (worker.json's "failing").
void robustnessTable(std::ostringstream& h, const nlohmann::json& r) {
    const auto failing = r.value("failing", nlohmann::json::array());
    h << "<p>" << r.value("cases", 0) << " hard cases, " << r.value("failed", 0) << " failed"
      << (failing.size() < size_t(r.value("failed", 0)) ? " (the first " + std::to_string(failing.size()) + " listed)" : "")
      << ".</p>\n";
    if (failing.empty()) return;
    h << "<table class=\"metrics\"><tr><th>case</th><th>moments b</th><th>zf</th><th>G</th><th>problems</th></tr>\n";
    for (const auto& c : failing) {
        std::string b;
        for (const auto& v : c.value("b", nlohmann::json::array())) b += (b.empty() ? "" : ", ") + number(v, 7);
        h << "<tr><td>" << htmlEscape(c.value("case", "")) << "</td><td>(" << b << ")</td><td>"
          << number(c.value("zf", nlohmann::json(0)), 7) << "</td><td>" << number(c.value("G", nlohmann::json(0)), 7)
          << "</td><td>" << htmlEscape(c.value("problems", "")) << "</td></tr>\n";
    }
    h << "</table>\n";
}

}  // namespace

ReportWriter::ReportWriter(std::filesystem::path dir)
    : dir_(std::move(dir)), staffDir_(dir_.parent_path() / "report-staff") {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
    std::filesystem::remove_all(staffDir_, ec);
    std::filesystem::create_directories(dir_ / "img");
}

void ReportWriter::add(const TestResult& t, const std::string& image, const Image& ref,
                       const Image& student, const Comparison& c, const ImageFindings& findings) {
    const std::filesystem::path folder = t.hidden ? staffDir_ : dir_;
    std::filesystem::create_directories(folder / "img");
    std::string base = "img/";
    for (char ch : t.scene + "_" + t.stage + "_" + image)
        base += std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' ? ch : '-';
    const bool srgb = isImage(image, ImageKind::Final);
    if (image == kSatKernelImage && ref.channels == 2) {  // widths in texels: shown over the
                                                         // reference's widest, as RGB
        const float largest = satKernelLargest(ref);
        return add(t, image, satKernelPreview(ref, largest), satKernelPreview(student, largest), c, findings);
    }
    const int step = stepFor(ref);
    const bool sameSize = student.width == ref.width && student.height == ref.height;
    // Full-size images where something is wrong and the preview is reduced; not where most of
    // the student's image is the stub value (magenta: the reduced preview says it, and three
    // full-size PNGs per image were most of a stub grade's report time).
    const bool stub = sameSize && 2 * c.stubTexels >= long(student.width) * student.height;
    const bool full =
        step > 1 && !stub && (c.fraction < 1.0 || c.nonFinite > 0 || !c.error.empty());
    Entry e;
    e.scene = t.scene, e.stage = t.stage, e.image = image, e.hidden = t.hidden;
    e.metrics = c.toJson();
    e.ref = base + "_ref.png";
    writePngPreview(reduce(ref, step, false), folder / e.ref, srgb);
    if (full) writePngPreview(ref, folder / (e.refFull = base + "_ref_full.png"), srgb);
    if (sameSize) {
        e.student = base + "_student.png";
        writePngPreview(reduce(student, step, false), folder / e.student, srgb);
        if (full) writePngPreview(student, folder / (e.studentFull = base + "_student_full.png"), srgb);
    }
    if (!c.errorMap.empty()) {
        e.diff = base + "_diff.png";
        writePngPreview(heatMap(reduce(c.errorMap, step, true)), folder / e.diff, false);
        if (full) writePngPreview(heatMap(c.errorMap), folder / (e.diffFull = base + "_diff_full.png"), false);
    }
    findings_.push_back(findings);
    entries_.push_back(std::move(e));
}

void ReportWriter::add(const TestResult& t, const std::string& image, const Image& ref,
                       const Image& student, const Comparison& c) {
    ImageFindings f = findImageProblems(c.errorMap, c.nonFinite, image);
    f.scene = t.scene, f.stage = t.stage, f.image = image, f.hidden = t.hidden;
    add(t, image, ref, student, c, f);
}

std::string ReportWriter::page(const GradeSummary& s, bool staff) const {
    auto shown = [&](bool hidden) { return staff || !hidden; };
    double score = 0, max = 0;
    int hiddenTests = 0;
    for (const auto& t : s.tests) {
        if (t.hidden) ++hiddenTests;
        if (!shown(t.hidden)) continue;
        score += t.score, max += t.maxScore;
    }
    std::set<std::string> hiddenScenes;
    for (const auto& t : s.tests)
        if (t.hidden) hiddenScenes.insert(t.scene);
    auto namesHidden = [&](const std::string& text) {
        for (const auto& n : hiddenScenes)
            if (text.find(n) != std::string::npos) return true;
        return false;
    };
    std::ostringstream h;
    h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
      << "<title>Shadowlab grade report" << (staff ? " (staff)" : "") << "</title><style>"
      << "body{font-family:sans-serif;margin:2em;background:#fafafa;color:#222}"
      << "table{border-collapse:collapse;margin:0.5em 0}td,th{border:1px solid #ccc;padding:4px 8px;vertical-align:top;text-align:left}"
      << ".passed{background:#e6f4e6}.failed{background:#fbe3e3}pre{white-space:pre-wrap;margin:0;font-size:12px}"
      << ".metrics{font-size:13px}.hidden-badge{background:#333;color:#fff;padding:1px 6px;border-radius:3px;font-size:12px}"
      << ".imgs{display:flex;gap:12px;flex-wrap:wrap}.imgs figure{margin:0}"
      << ".imgs img{width:256px;image-rendering:pixelated;border:1px solid #999;background:#000}"
      << "</style></head><body>\n<h1>Shadowlab grade: " << fixedDigits(score) << " / " << fixedDigits(max) << "</h1>\n";
    if (staff)
        h << "<p><b>Staff report:</b> every test, hidden scenes marked <span class=\"hidden-badge\">hidden"
             "</span>. Do not forward it; <code>report/</code> is the one students may see.</p>\n";
    else if (hiddenTests)
        h << "<p>Visible tests only: " << hiddenTests << " tests on hidden scenes are graded too; "
             "they are shown after the due date.</p>\n";
    h << "<p>Reference: " << htmlEscape(s.referenceMode) << ". Heat-maps: black = equal, blue to cyan = "
         "within tolerance, yellow to red = outside it (1&times; to 1000&times; the tolerance). "
         "Click an image for its full size.</p>\n";
    for (const auto& w : s.warnings)
        if (staff || !namesHidden(w)) h << "<p><b>warning:</b> " << htmlEscape(w) << "</p>\n";

    // Summary per stage.
    h << "<h2>Summary</h2>\n<table><tr><th>stage</th><th>points</th><th>tests passed</th><th>lost on</th></tr>\n";
    for (const auto& stage : stageNames()) {
        double got = 0, of = 0;
        int n = 0, passed = 0;
        std::string lostOn;
        for (const auto& t : s.tests) {
            if (t.stage != stage || !shown(t.hidden)) continue;
            got += t.score, of += t.maxScore, ++n;
            if (!t.lostPoints()) ++passed;
            else lostOn += (lostOn.empty() ? "" : ", ") + htmlEscape(t.scene) + (t.hidden ? " (hidden)" : "");
        }
        if (!n) continue;
        h << "<tr class=\"" << (passed == n ? "passed" : "failed") << "\"><td>" << stage << "</td><td>"
          << fixedDigits(got) << " / " << fixedDigits(of) << "</td><td>" << passed << " of " << n << "</td><td>"
          << (lostOn.empty() ? "full marks" : lostOn) << "</td></tr>\n";
    }
    h << "</table>\n";
    const auto findings = diagnose(s, findings_, staff);
    if (!findings.empty()) {
        h << "<h2>What the failures look like</h2>\n<ul>\n";
        for (const auto& f : findings) h << "<li>" << htmlEscape(f) << "</li>\n";
        h << "</ul>\n";
    }

    // Every test, then the details.
    h << "<h2>Tests</h2>\n<table><tr><th>scene</th><th>stage</th><th>points</th><th>reason</th></tr>\n";
    for (const auto& t : s.tests) {
        if (!shown(t.hidden)) continue;
        h << "<tr class=\"" << (t.lostPoints() ? "failed" : "passed") << "\"><td><a href=\"#"
          << anchor(t.scene, t.stage) << "\">" << htmlEscape(t.scene) << "</a>"
          << (t.hidden ? " <span class=\"hidden-badge\">hidden</span>" : "") << "</td><td>" << t.stage
          << "</td><td>" << fixedDigits(t.score) << " / " << fixedDigits(t.maxScore) << "</td><td>"
          << htmlEscape(t.output.substr(0, t.output.find('\n'))) << "</td></tr>\n";
    }
    h << "</table>\n";
    for (const auto& t : s.tests) {
        if (!shown(t.hidden)) continue;
        h << "<h2 id=\"" << anchor(t.scene, t.stage) << "\">" << htmlEscape(t.scene) << ": " << t.stage
          << (t.hidden ? " <span class=\"hidden-badge\">hidden</span>" : "") << "</h2>\n<pre>"
          << htmlEscape(t.output) << "</pre>\n";
        if (t.metrics.contains("robustness")) robustnessTable(h, t.metrics["robustness"]);
        for (const auto& e : entries_) {
            if (e.scene != t.scene || e.stage != t.stage) continue;
            // The staff page sits next to report/: public images are linked there.
            const std::string prefix = staff && !e.hidden ? "../report/" : "";
            h << "<h3>" << htmlEscape(e.image) << "</h3><div class=\"imgs\">";
            auto fig = [&](const std::string& src, const std::string& fullSrc, const char* caption) {
                if (src.empty()) {
                    h << "<figure><figcaption>" << caption << ": none</figcaption></figure>";
                    return;
                }
                const std::string link = prefix + (fullSrc.empty() ? src : fullSrc);
                h << "<figure><a href=\"" << link << "\"><img src=\"" << prefix << src << "\" alt=\""
                  << caption << "\"></a><figcaption>" << caption << " (<a href=\"" << link
                  << "\">full size</a>)</figcaption></figure>";
            };
            fig(e.ref, e.refFull, "reference");
            fig(e.student, e.studentFull, "submission");
            fig(e.diff, e.diffFull, "difference");
            h << "</div>\n";
            metricsTable(h, e.metrics);
        }
    }
    h << "</body></html>\n";
    return h.str();
}

void ReportWriter::finish(const GradeSummary& s) {
    std::ofstream(dir_ / "index.html") << page(s, false);
    bool hidden = false;
    for (const auto& t : s.tests) hidden = hidden || t.hidden;
    if (!hidden) return;
    std::filesystem::create_directories(staffDir_);
    std::ofstream(staffDir_ / "index.html") << page(s, true);
}


}  // namespace sl::grader
