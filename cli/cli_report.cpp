// cli_report: `shadowlab report` renders the images the assignment's report asks for from a
// solution's own stages (the student's, by default; `./kit report`):
//   - the moment map before and after the blur (moments_before_blur.png, moments_after_blur.png),
//   - the softness ladder, scenes/ladder/softness_<i>.json, from "a point-like light" to "a very
//     wide light" (softness_<i>.png), each pixel's box from satKernelTexels,
//   - one scene's penumbra growing with distance, scenes/penumbra.json (penumbra.png),
// and one index.html that shows them with captions. Every link is relative and nothing else is
// written, so the folder can be zipped and handed in. Stubbed stages do not stop it: their
// images show the stub value in magenta and the page names the stages still to implement.
#include "cli_commands.h"
#include "gl_context.h"
#include "html_escape.h"
#include "image_io.h"
#include "pass_plan.h"
#include "paths.h"
#include "renderer.h"
#include "scene.h"
#include "scene_size.h"
#include "stub_survey.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <regex>

namespace sl::cli {
namespace {

struct LadderStep {
    Scene scene;
    std::string phrase;  // "a point-like light" ... from the scene's description
};

// scenes/ladder/softness_<i>.json in the order of i (softness_10 after softness_9).
std::vector<fs::path> ladderScenes(const fs::path& root) {
    std::vector<std::pair<int, fs::path>> found;
    static const std::regex name(R"(softness_(\d+)\.json)");
    std::smatch m;
    if (fs::is_directory(root / "scenes/ladder"))
        for (const auto& e : fs::directory_iterator(root / "scenes/ladder")) {
            const std::string file = e.path().filename().string();
            if (std::regex_match(file, m, name)) found.emplace_back(std::stoi(m[1]), e.path());
        }
    std::sort(found.begin(), found.end());
    std::vector<fs::path> out;
    for (auto& f : found) out.push_back(f.second);
    if (out.size() < 2)
        throw std::runtime_error((root / "scenes/ladder").string() +
                                 ": expected softness_1.json, softness_2.json, ... (the softness ladder)");
    return out;
}

// The ladder scenes say what each step looks like after an em dash: "... — a very wide light: ...".
std::string ladderPhrase(const std::string& description) {
    static const std::regex phrase("\u2014 ([^:.]+)");
    std::smatch m;
    return std::regex_search(description, m, phrase) ? m[1].str() : "";
}

// The same softness with the other filter: a Gaussian with the variance of the SAT's box of
// width w (σ = w / √12), cut at 2σ (at least one texel); a per-pixel box's w is its largest
// search box, which the ladder widens with the light.
void useFilter(ShadowEffect& fx, FilterKind filter) {
    if (filter == fx.filter) return;
    if (filter == FilterKind::Gaussian) {
        fx.gaussianSigma = float(fx.satKernelTexels / std::sqrt(12.0));
        fx.gaussianRadius = std::clamp(int(std::ceil(2.0 * fx.gaussianSigma)), 1, 64);
    } else {
        const double sigma = fx.gaussianSigma > 0 ? fx.gaussianSigma : fx.gaussianRadius / 2.0;
        fx.satKernelTexels = float(std::max(1.0, sigma * std::sqrt(12.0)));
    }
    fx.filter = filter;
}

std::string filterWords(const ShadowEffect& fx) {
    char s[160];
    if (fx.filter == FilterKind::Sat && fx.satPerPixel)
        std::snprintf(s, sizeof s, "summed-area table, per-pixel box (satKernelTexels: search up "
                      "to %.3g, box up to %.3g texels)", fx.satKernelTexels, fx.satMaxKernelTexels);
    else if (fx.filter == FilterKind::Sat)
        std::snprintf(s, sizeof s, "summed-area table, box of %.3g texels", fx.satKernelTexels);
    else
        std::snprintf(s, sizeof s, "Gaussian, radius %d, σ = %.2f texels", fx.gaussianRadius,
                      fx.gaussianSigma > 0 ? fx.gaussianSigma : fx.gaussianRadius / 2.0f);
    return std::string(s) + " on a " + std::to_string(fx.mapSize) + "² map";
}

// What the ladder shows with the filter it was rendered with: the SAT's per-pixel boxes follow
// the blockers, the Gaussian's one kernel does not.
std::string ladderWords(FilterKind filter) {
    if (filter == FilterKind::Sat)
        return "With the summed-area table each pixel's box is the penumbra its blockers cast "
               "(satKernelTexels), so shadows widen with the light and stay sharp where a caster "
               "meets the ground; wider boxes average the moments of more depths, so the "
               "reconstructed shadow's penumbra widens.";
    return "With the Gaussian every pixel is blurred with one kernel, its width set by the "
           "light's size: shadows widen with the light everywhere alike, even where a caster "
           "meets the ground (the summed-area table's per-pixel boxes keep those sharp; the "
           "report shows them once sat.comp and sat_lookup.glsl are implemented).";
}

std::string penumbraWords(FilterKind filter) {
    if (filter == FilterKind::Sat)
        return "The post's shadow is sharp at its foot and widens toward its tip; the raised "
               "slab's shadow is wide all round.";
    return "With the Gaussian's one kernel the post's shadow is as soft at its foot as at its "
           "tip; the summed-area table's per-pixel boxes make it sharp at the foot and wider "
           "toward the tip.";
}

bool mentionsFilter(const std::vector<std::string>& notes, FilterKind filter) {
    for (const auto& n : notes) {
        const bool sat = n.find("sat.comp") != std::string::npos || n.find("sat_lookup.glsl") != std::string::npos;
        const bool gauss = n.find("gaussian_blur.comp") != std::string::npos;
        if (filter == FilterKind::Sat ? sat : gauss) return true;
    }
    return false;
}

// "auto": the ladder's own filter if the solution implements it, else the other one if that is
// implemented (the "either" rubric lets a student do one filter), else the ladder's own. Found
// by a render of the first step at a tiny size, which notes each stubbed stage.
FilterKind chooseFilter(Renderer& renderer, const Scene& first, const std::string& wanted,
                        std::string& why) {
    if (wanted == "sat" || wanted == "gaussian") {
        why = "chosen with --filter " + wanted;
        return wanted == "sat" ? FilterKind::Sat : FilterKind::Gaussian;
    }
    const FilterKind own = first.shadow.filter;
    const FilterKind other = own == FilterKind::Sat ? FilterKind::Gaussian : FilterKind::Sat;
    for (FilterKind f : {own, other}) {
        Scene tiny = first;
        tiny.cameras.resize(1);
        scaleScene(tiny, 32);
        useFilter(tiny.shadow, f);
        // With the filtered map: a stub satBoxAverage shows there (the lit image cannot say).
        const RenderResult r = renderer.render(tiny, planPasses(tiny, {.resolveSat = true}));
        for (const auto& n : r.stubNotes)
            if (n.find("moments.glsl") != std::string::npos) {
                why = "the ladder's own; with moments.glsl a stub no filter can be checked";
                return own;
            }
        if (!mentionsFilter(r.stubNotes, f)) {
            why = f == own ? "the ladder's own filter" : std::string("the ladder's ") + toString(own) +
                                                             " filter is a stub here; this one is not";
            return f;
        }
    }
    why = "neither filter is implemented yet";
    return own;
}

// One moment map shown as a 2×2 grid of grey images, b1 (top left), b2, b3, b4, each a
// `crop`-texel window of the map scaled to `cell` pixels (nearest), each channel stretched
// linearly from `lo` to `hi`. Stub texels (-1) stay -1: magenta in the PNG. Rows bottom first.
Image momentGrid(const Image& map, int x0, int y0, int crop, int cell, const float lo[4],
                 const float hi[4]) {
    const int pad = 4, side = 2 * cell + 3 * pad;
    Image out(side, side, 1, 0.12f);
    for (int c = 0; c < 4; ++c) {
        const int gx = pad + (c % 2) * (cell + pad);
        const int gy = pad + (1 - c / 2) * (cell + pad);  // b1, b2 on the top row
        for (int y = 0; y < cell; ++y)
            for (int x = 0; x < cell; ++x) {
                const int mx = x0 + x * crop / cell, my = y0 + y * crop / cell;
                bool stub = true;
                for (int k = 0; k < map.channels; ++k) stub &= map.at(mx, my, k) == -1.0f;
                const float v = map.at(mx, my, std::min(c, map.channels - 1));
                out.at(gx + x, gy + y, 0) = stub ? -1.0f : std::clamp((v - lo[c]) / (hi[c] - lo[c]), 0.0f, 1.0f);
            }
    }
    return out;
}

// The `crop`-texel window of `map` whose b1 has the most edges (shadow casters' outlines):
// the blur shows there. Sum of |∂x b1| + |∂y b1| over windows at a stride of crop / 8.
void busiestWindow(const Image& map, int crop, int& bx, int& by) {
    bx = (map.width - crop) / 2, by = (map.height - crop) / 2;
    const int step = std::max(1, crop / 8);
    double best = 0.0;
    for (int y0 = 0; y0 + crop <= map.height; y0 += step)
        for (int x0 = 0; x0 + crop <= map.width; x0 += step) {
            double e = 0.0;
            for (int y = y0; y + 1 < y0 + crop; y += 2)
                for (int x = x0; x + 1 < x0 + crop; x += 2) {
                    const float v = map.at(x, y, 0);
                    if (v == -1.0f) continue;
                    e += std::abs(map.at(x + 1, y, 0) - v) + std::abs(map.at(x, y + 1, 0) - v);
                }
            if (e > best) best = e, bx = x0, by = y0;
        }
}

// Writes the before/after pair from one render; returns the caption's window description.
std::string writeMomentPair(const RenderResult& r, const fs::path& out) {
    const Image& raw = r.images.at("moments_raw");
    const Image& filtered = r.images.at("moments_filtered");
    const int crop = std::min({256, raw.width, raw.height});
    const int cell = 256;
    int x0, y0;
    busiestWindow(raw, crop, x0, y0);
    // One stretch per channel from the raw window, used for both images so that they compare.
    float lo[4], hi[4];
    for (int c = 0; c < 4; ++c) {
        lo[c] = 1e30f, hi[c] = -1e30f;
        for (int y = y0; y < y0 + crop; ++y)
            for (int x = x0; x < x0 + crop; ++x) {
                const float v = raw.at(x, y, std::min(c, raw.channels - 1));
                if (v == -1.0f || !std::isfinite(v)) continue;
                lo[c] = std::min(lo[c], v), hi[c] = std::max(hi[c], v);
            }
        if (!(hi[c] - lo[c] > 1e-12f)) lo[c] = 0.0f, hi[c] = 1.0f;
    }
    writePngPreview(momentGrid(raw, x0, y0, crop, cell, lo, hi), out / "moments_before_blur.png", false);
    writePngPreview(momentGrid(filtered, x0, y0, crop, cell, lo, hi), out / "moments_after_blur.png", false);
    char s[200];
    std::snprintf(s, sizeof s, "a %d×%d-texel window of the %d×%d map (texels %d–%d across, %d–%d up)",
                  crop, crop, raw.width, raw.height, x0, x0 + crop - 1, y0, y0 + crop - 1);
    return s;
}

std::string notesHtml(const std::vector<std::string>& notes) {
    std::string s;
    for (const auto& n : notes) s += "<div class=\"stub\">" + htmlEscape(n) + "</div>";
    return s;
}

int runReport(const std::string& solution, const std::string& outDir, int size,
              const std::string& filterWanted, const std::string& backend) {
    const fs::path root = repoRoot();
    std::vector<LadderStep> ladder;
    for (const auto& p : ladderScenes(root)) {
        Scene s = loadScene(p.string());
        ladder.push_back({s, ladderPhrase(s.description)});
    }
    auto context = createContext(parseBackendKind(backend));
    Renderer renderer(ShaderLibrary::forSolution(resolveSolution(solution), root));
    std::string why;
    const FilterKind filter = chooseFilter(renderer, ladder[0].scene, filterWanted, why);

    const fs::path out = outDir;
    fs::create_directories(out);
    // The moment maps come from the middle step: a blur wide enough to see at texel scale.
    const size_t momentStep = ladder.size() / 2;
    std::vector<std::string> allNotes;
    std::string ladderHtml, momentHtml;
    for (size_t i = 0; i < ladder.size(); ++i) {
        Scene& scene = ladder[i].scene;
        scene.cameras.resize(1);  // the main camera's image is the one shown
        scaleScene(scene, size);
        useFilter(scene.shadow, filter);
        // Only the step whose moment maps are shown needs the filtered map.
        const PassPlan plan = planPasses(scene, {.resolveSat = i == momentStep});
        RenderResult r = renderer.render(scene, plan);
        if (i == momentStep) completeStubNotes(renderer.library(), plan, r);  // one stub hides another
        for (const auto& n : r.stubNotes)
            if (std::find(allNotes.begin(), allNotes.end(), n) == allNotes.end()) allNotes.push_back(n);
        const std::string png = "softness_" + std::to_string(i + 1) + ".png";
        writePngPreview(r.images.at("final"), out / png, true);
        ladderHtml += "<figure><a href=\"" + png + "\"><img src=\"" + png + "\" alt=\"" + png +
                      "\"></a><figcaption><b>" + std::to_string(i + 1) + ". " +
                      htmlEscape(ladder[i].phrase) + "</b><br>" + htmlEscape(filterWords(scene.shadow)) +
                      notesHtml(r.stubNotes) + "</figcaption></figure>\n";
        if (i == momentStep) {
            const std::string window = writeMomentPair(r, out);
            std::string cap = "Step " + std::to_string(i + 1) + " of the ladder (" +
                              filterWords(scene.shadow) + "), " + window + ".";
            if (scene.shadow.filter == FilterKind::Sat && scene.shadow.satPerPixel) {
                char box[200];
                std::snprintf(box, sizeof box, " After the blur: each texel's average over the "
                              "search box (%.3g texels), the widest a pixel's own box can reach; "
                              "lighting takes each pixel's box from the table.",
                              scene.shadow.satKernelTexels);
                cap += box;
            }
            momentHtml =
                "<figure><a href=\"moments_before_blur.png\"><img src=\"moments_before_blur.png\" "
                "alt=\"moments before the blur\"></a><figcaption><b>Before the blur</b> (moments.glsl)"
                "</figcaption></figure>\n<figure><a href=\"moments_after_blur.png\"><img "
                "src=\"moments_after_blur.png\" alt=\"moments after the blur\"></a><figcaption><b>"
                "After the blur</b> (" + std::string(filter == FilterKind::Sat ? "sat.comp + sat_lookup.glsl" : "gaussian_blur.comp") +
                ")</figcaption></figure>\n<p>" + htmlEscape(cap) + notesHtml(r.stubNotes) + "</p>\n";
        }
    }
    // The second figure: one scene's penumbra growing with the blocker-receiver distance.
    std::string penumbraHtml;
    {
        Scene scene = loadScene((root / "scenes/penumbra.json").string());
        scene.cameras.resize(1);
        scaleScene(scene, size);
        useFilter(scene.shadow, filter);
        const PassPlan plan = planPasses(scene);
        RenderResult r = renderer.render(scene, plan);
        completeStubNotes(renderer.library(), plan, r);  // the per-pixel kernel, if a stub
        for (const auto& n : r.stubNotes)
            if (std::find(allNotes.begin(), allNotes.end(), n) == allNotes.end()) allNotes.push_back(n);
        writePngPreview(r.images.at("final"), out / "penumbra.png", true);
        penumbraHtml = "<figure><a href=\"penumbra.png\"><img src=\"penumbra.png\" "
                       "alt=\"penumbra.png\"></a><figcaption>" +
                       htmlEscape(filterWords(scene.shadow)) + notesHtml(r.stubNotes) +
                       "</figcaption></figure>\n";
    }

    std::ofstream html(out / "index.html");
    html << "<!doctype html><meta charset=\"utf-8\"><title>Moment shadow mapping: report images"
            "</title>\n<style>body{font-family:sans-serif;max-width:1100px;margin:auto;padding:0 1em}"
            " .row{display:flex;flex-wrap:wrap;gap:12px} figure{margin:0;width:min(100%,260px)}"
            " .moments figure{width:min(100%,420px)} img{width:100%;image-rendering:pixelated}"
            " .stub{color:#b0006e;font-size:90%}</style>\n"
         << "<h1>Moment shadow mapping: report images</h1>\n<p>Rendered by <code>shadowlab report"
            "</code> from the stages in <code>" << htmlEscape(solution) << "</code> with "
         << htmlEscape(context->info().renderer) << ", " << htmlEscape(context->info().version)
         << ". Filter: " << toString(filter) << " (" << htmlEscape(why) << ").</p>\n";
    if (!allNotes.empty())
        html << "<p><b>Stages still to implement</b> (their output is the stub value −1, shown in "
                "magenta):</p>" << notesHtml(allNotes) << "\n";
    html << "<h2>The moment map before and after the blur</h2>\n<p>Each image shows the four "
            "moments the shadow map stores, b1 = z (top left), b2 = z² (top right), b3 = z³ "
            "(bottom left) and b4 = z⁴ (bottom right), z the depth relative to the light, each "
            "in grey from the smallest (black) to the largest (white) value of that moment in "
            "the raw window; the same scale in both images, so they compare. Blurring the "
            "moments averages the depth distribution each texel's kernel sees: sharp outlines "
            "become ramps.</p>\n<div class=\"row moments\">\n" << momentHtml
         << "</div>\n<h2>The softness ladder</h2>\n<p>The same scene, one light growing step "
            "by step: from a point-like light to a very wide one. " << ladderWords(filter)
         << "</p>\n<div class=\"row\">\n" << ladderHtml << "</div>\n"
         << "<h2>The penumbra and the distance to the caster</h2>\n<p>One scene (scenes/penumbra.json). "
         << penumbraWords(filter) << "</p>\n<div class=\"row\">\n" << penumbraHtml << "</div>\n";
    html.close();

    std::cout << "wrote " << (out / "index.html").string() << ", moments_before_blur.png, "
              << "moments_after_blur.png, softness_1.." << ladder.size() << ".png and penumbra.png (" << solution
              << ", " << toString(filter) << " filter: " << why << ")\n";
    for (const auto& n : allNotes) std::cout << "note: " << n << "\n";
    return Ok;
}

}  // namespace

void addReportCommand(CLI::App& app, Context& ctx) {
    auto* report = app.add_subcommand(
        "report", "the assignment's report images: moments before/after the blur, the softness ladder");
    struct Args {
        std::string solution = "student", out = "out/report", filter = "auto";
        int size = 512;
    };
    auto a = std::make_shared<Args>();
    report->add_option("--solution", a->solution, "reference, student, or a folder of stage files");
    report->add_option("--out", a->out, "output folder (index.html and its PNGs)");
    report->add_option("--size", a->size,
                       "image side in pixels; the shadow map and the filter widths scale with it")
        ->check(CLI::Range(32, 4096));
    report->add_option("--filter", a->filter,
                       "auto (the ladder's SAT if implemented, else the Gaussian), sat or gaussian")
        ->check(CLI::IsMember({"auto", "sat", "gaussian"}));
    report->callback([a, &ctx] {
        ctx.exitCode = runReport(a->solution, a->out, a->size, a->filter, ctx.backend);
    });
}

}  // namespace sl::cli
