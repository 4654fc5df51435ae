// report_diagnosis: each pattern is a plain rule over the scored tests:
//   border     most of an image's failing texels lie in a band along its edge (a red frame
//              in the heat-map): the filter's or the lookup's border rule;
//   SAT only   points lost on SAT scenes only, while Gaussian scenes pass the same stages;
//   far        a SAT stage's failing texels lie in the half of the map away from the table's
//              origin, or along its two far edges alone, where its sums are largest: a plain
//              float table's rounding (there the border finding is not drawn);
//   widths     only a per-pixel SAT's box widths fail, every box average passes: satKernelTexels;
//   NaN        non-finite values in an image, or NaN/Inf among the failing hard cases;
//   bias       failing hard cases in the sets whose Hankel matrix is singular without the
//              moment bias (constant depth, two/three points, c3 = 0, 16-bit moments);
//   guards     hard cases outside [0, 1] or non-monotone: the clamps and pivot floors;
//   interface  `final` loses points while every isolated stage of that scene passes;
//   ladder     the moments stage's relativeDepth ladder fails (outside [near, far]: no clamp).
// A stage that is still the stub ("not implemented: ...") gets no diagnosis: it is no bug.
#include "report_diagnosis.h"

#include "depth_ladder.h"
#include "sat_kernel_ladder.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>

namespace sl::grader {
namespace {

std::string list(const std::set<std::string>& items) {
    std::string s;
    for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
    return s;
}

std::string percent(double v) {
    char b[16];
    std::snprintf(b, sizeof b, "%.0f%%", 100.0 * v);
    return b;
}

}  // namespace

ImageFindings findImageProblems(const Image& e, long nonFinite, const std::string& image) {
    ImageFindings f;
    f.nonFinite = nonFinite;
    if (e.empty()) return f;
    if (image == kDepthLadderImage) {
        f.depthLadder = true;
        const auto& rows = relativeDepthLadder();
        f.rows = e.width;
        for (int x = 0; x < e.width; ++x) {
            if (e.at(x, 0, 0) <= 1.0f) continue;  // NaN counts as failing
            ++f.failing;
            if (size_t(x) < rows.size() && (rows[x].x < rows[x].y || rows[x].x > rows[x].z))
                ++f.failingOutsideRange;
        }
        return f;
    }
    // A border rule reaches as far as the filter does: up to the kernel's radius (<= 32 in
    // the public scenes' maps of 512-2048 texels), so the band grows with the map.
    f.band = std::max(4, std::max(e.width, e.height) / 32);
    for (int y = 0; y < e.height; ++y)
        for (int x = 0; x < e.width; ++x) {
            if (!(e.at(x, y, 0) <= 1.0f)) {  // NaN counts as failing
                ++f.failing;
                const int edge = std::min(std::min(x, e.width - 1 - x), std::min(y, e.height - 1 - y));
                if (edge < f.band) {
                    ++f.failingNearBorder, f.reach = std::max(f.reach, edge + 1);
                    if (std::min(x, y) >= f.band) ++f.failingFarEdges;
                }
                // x/W + y/H > 1: the half of the map whose table entries sum the most texels.
                if (double(x) * e.height + double(y) * e.width > double(e.width) * e.height)
                    ++f.failingFar;
            }
        }
    return f;
}

std::string depthLadderText(const ImageFindings& f) {
    std::string text = "the depth-ladder probe finds " + std::to_string(f.failing) + " of its " +
                       std::to_string(f.rows) + " light depths off";
    if (f.failing > 0 && f.failingOutsideRange == f.failing)
        return text + ", all outside [near, far]: relativeDepth must clamp (d - near) / (far - near) "
                      "to [0, 1]";
    if (f.failingOutsideRange > 0)
        return text + " (" + std::to_string(f.failingOutsideRange) + " outside [near, far], " +
               std::to_string(f.failing - f.failingOutsideRange) +
               " inside): look at relativeDepth, then computeMoments";
    if (f.failingDepth == 0)  // every failing rung has the right z: the powers are off
        return text + ", inside [near, far], each with the right b1 = z: relativeDepth is right, "
                      "look at computeMoments";
    return text + ", inside [near, far]: look at relativeDepth, then computeMoments";
}

std::vector<std::string> diagnose(const GradeSummary& s, const std::vector<ImageFindings>& images,
                                  bool includeHidden) {
    std::vector<std::string> out;
    auto shown = [&](bool hidden) { return includeHidden || !hidden; };

    // The relativeDepth ladder: one row of light depths (no border, no map), the same rows in
    // every scene's moments test: one line per outcome, with its scenes.
    std::map<std::string, std::set<std::string>> ladders;
    for (const auto& f : images)
        if (shown(f.hidden) && f.depthLadder && f.failing > 0) ladders[depthLadderText(f)].insert(f.scene);
    for (const auto& [text, scenes] : ladders)
        out.push_back(list(scenes) + " (moments): " + text +
                      " (docs/stage_contract.md); `shadowlab probe moments --generate "
                      "depth-ladder` writes its rows with the expected moments.");

    // Border: a red frame. Not on a per-pixel SAT's box widths that fail along the far edges
    // alone: the ladder's cells sit inside the map (no filter border there), and its blocker
    // searches near the far edges read the table's largest sums (the precision finding below).
    auto farEdgesOnly = [](const ImageFindings& f) {
        return f.stage == "sat" && f.image == kSatKernelImage && f.failingFarEdges >= 0.9 * f.failingNearBorder;
    };
    // Only where points were lost, and only on maps (a camera image's edge is no filter's).
    std::set<std::pair<std::string, std::string>> lost;
    for (const auto& t : s.tests)
        if (t.lostPoints()) lost.insert({t.scene, t.stage});
    for (const auto& f : images) {
        if (!shown(f.hidden) || f.depthLadder || f.failing < 4 || f.failingNearBorder < 0.9 * f.failing ||
            farEdgesOnly(f) || !lost.count({f.scene, f.stage}) || f.stage == "final" || f.stage == "msm")
            continue;
        const bool sat = f.stage == "sat";
        out.push_back(f.scene + " (" + f.stage + ", " + f.image + "): " +
                      percent(double(f.failingNearBorder) / f.failing) + " of the " +
                      std::to_string(f.failing) + " texels outside tolerance lie within " +
                      std::to_string(f.reach) + " texels of the border (a red frame in the "
                      "heat-map): check the border rule" +
                      (sat ? " (the table's index -1 is the zero border; a box is clipped to "
                             "the map, docs/stage_contract.md)"
                           : f.stage == "gaussian" ? " (taps outside the map clamp to the edge "
                                                     "texel, docs/stage_contract.md)"
                                                   : "") + ".");
    }

    // Far from the origin: a float table's entry S(x, y) sums (x+1)(y+1) texels and rounds in
    // proportion, so its box averages fail where x and y are large. Failures of a wrong corner
    // or area fall on both halves alike (15 of 16 on the far half by chance: 1 in 3 855);
    // those of a border rule lie in the frame (the finding above), often its far edges.
    const std::string floatSum = "a float sum of up to a million texels keeps too few digits for a "
                                 "small box's average (keep the running sums in double, or store the "
                                 "table with an offset: docs/numerics.md, section 5).";
    bool precision = false;  // some SAT image fails where the sums are largest
    for (const auto& f : images) {
        if (!shown(f.hidden) || f.stage != "sat" || f.failing < 4) continue;
        const size_t before = out.size();
        if (f.failingNearBorder >= 0.9 * f.failing && farEdgesOnly(f))
            out.push_back(f.scene + " (sat, " + f.image + "): " +
                          percent(double(f.failingFarEdges) / f.failing) + " of the " +
                          std::to_string(f.failing) + " texels outside tolerance lie along the two "
                          "edges of the map away from texel (0, 0), where the table's sums are "
                          "largest, and not along the two through it: " + floatSum);
        else if (f.failing >= 16 && f.failingFar >= 0.9 * f.failing && f.failingNearBorder < 0.9 * f.failing)
            out.push_back(f.scene + " (sat, " + f.image + "): " +
                          percent(double(f.failingFar) / f.failing) + " of the " +
                          std::to_string(f.failing) + " texels outside tolerance lie in the half of "
                          "the map away from texel (0, 0), where the table's sums are largest: " + floatSum);
        precision = precision || out.size() > before;
    }

    // SAT only / Gaussian only: the scenes' filters, from the filter tests that exist.
    std::set<std::string> satScenes, gaussScenes, lostScenes, lostSat, lostGauss;
    for (const auto& t : s.tests) {
        if (!shown(t.hidden)) continue;
        if (t.stage == "sat") satScenes.insert(t.scene);
        if (t.stage == "gaussian") gaussScenes.insert(t.scene);
    }
    for (const auto& t : s.tests) {
        // Only renders that were compared: a timeout, crash or compile error says its own cause.
        if (!shown(t.hidden) || !t.lostPoints() || t.stage == "robustness" || t.notImplemented() ||
            t.images.empty())
            continue;
        lostScenes.insert(t.scene);
        if (satScenes.count(t.scene)) lostSat.insert(t.scene);
        if (gaussScenes.count(t.scene)) lostGauss.insert(t.scene);
    }
    // Of the SAT's images, only the per-pixel box widths fail, and not where the sums are
    // largest: the kernel, not the table.
    bool widthsFail = false, averagesFail = false;
    for (const auto& f : images)
        if (shown(f.hidden) && f.stage == "sat" && f.failing > 0)
            (f.image == kSatKernelImage ? widthsFail : averagesFail) = true;
    if (!lostScenes.empty() && lostSat == lostScenes && widthsFail && !averagesFail && !precision)
        out.push_back("Only the per-pixel box widths are off (" + list(lostSat) + "); every box "
                      "average passes, so the table and the lookup are right: look at "
                      "satKernelTexels in sat_lookup.glsl, each step as docs/stage_contract.md "
                      "fixes it (z_b clamped to [0, z_r], the fade-in over the blockers' first "
                      "5 %, the perspective scale, the floors and the largest box).");
    else if (!lostScenes.empty() && lostSat == lostScenes && !gaussScenes.empty())
        out.push_back("Points are lost only on the SAT scenes (" + list(lostSat) +
                      "); every Gaussian scene passes: look at sat.comp and sat_lookup.glsl "
                      "(the table's precision, docs/numerics.md, or the box's corners).");
    if (!lostScenes.empty() && lostGauss == lostScenes && !satScenes.empty())
        out.push_back("Points are lost only on the Gaussian scenes (" + list(lostGauss) +
                      "); every SAT scene passes: look at gaussian_blur.comp (weights, radius, "
                      "direction, the border).");

    // NaN / Inf in images.
    std::map<std::string, std::set<std::string>> nanStages;
    for (const auto& f : images)
        if (shown(f.hidden) && f.nonFinite > 0) nanStages[f.stage].insert(f.scene);
    for (const auto& [stage, scenes] : nanStages)
        out.push_back("NaN or Inf values in the " + stage + " stage's output (" + list(scenes) +
                      "): a division by zero, or a sqrt or log of a negative number, without a "
                      "guard.");

    // The hard cases, by case set (names are "<set>/<label>/zf...").
    static const std::set<std::string> biasSets = {"constant-depth", "two-point", "three-point",
                                                   "c3-zero", "quantized-16bit"};
    for (const auto& t : s.tests) {
        if (t.stage != "robustness" || !t.lostPoints() || t.notImplemented() ||
            !t.metrics.contains("robustness"))
            continue;
        const auto& failing = t.metrics["robustness"].value("failing", nlohmann::json::array());
        std::map<std::string, int> bySet;
        int nan = 0, range = 0, monotone = 0;
        for (const auto& c : failing) {
            const std::string name = c.value("case", "");
            ++bySet[name.substr(0, name.find('/'))];
            const std::string p = c.value("problems", "");
            nan += p.find("NaN") != std::string::npos || p.find("Inf") != std::string::npos;
            range += p.find("outside [0, 1]") != std::string::npos;
            monotone += p.find("non-monotone") != std::string::npos;
        }
        std::set<std::string> biased;
        int inBias = 0;
        for (const auto& [set, n] : bySet)
            if (biasSets.count(set)) biased.insert(set), inBias += n;
        // Ordinary two- and three-point distributions fail only when the solve itself is off (a
        // wrong Cholesky sign, swapped roots: 14 of their first 20 failures); without the bias
        // 2 of 12, without the guards none. Depths at exactly 0 and 1 and denormal moments then
        // tell the guards (they pass with the bias alone missing, msm_no_moment_bias).
        const int ordinary = bySet["two-point"] + bySet["three-point"];
        const int edge = bySet["depth-0-1"], denormal = bySet["denormals"];
        if (ordinary >= 3)
            out.push_back(std::to_string(ordinary) + " hard cases of ordinary two- and three-point "
                          "depth distributions fail: the solve itself looks off (the Cholesky "
                          "steps, the quadratic's roots and their order, the case selection; "
                          "docs/handout.md, section 3), not a guard or the bias.");
        else if (ordinary == 0 && (edge >= 3 || denormal >= 2))
            out.push_back("The hard cases at depths exactly 0 and 1 (" + std::to_string(edge) +
                          ") and with denormal moments (" + std::to_string(denormal) + ") fail, "
                          "ordinary distributions pass: the guards look missing (the pivot floors "
                          "of the Cholesky solve, the clamp of the quadratic's discriminant, the "
                          "final clamp to [0, 1]; docs/numerics.md).");
        else if (bySet.count("constant-depth") && bySet["constant-depth"] >= 3)
            out.push_back("The constant-depth hard cases fail together (" +
                          std::to_string(bySet["constant-depth"]) + "): the moment bias looks "
                          "missing (b' = (1 - a) b + a (0.5, 0.5, 0.5, 0.5) keeps the Hankel "
                          "matrix invertible when every depth is the same; docs/numerics.md).");
        else if (biased.size() >= 2 && 2 * inBias >= int(failing.size()))
            out.push_back("Most failing hard cases (" + std::to_string(inBias) + ") are in the "
                          "sets whose Hankel matrix is singular without the bias (" + list(biased) +
                          "): the moment bias looks missing or mixed the wrong way.");
        if (nan)
            out.push_back(std::to_string(nan) + " hard cases give NaN or Inf: a sqrt or a "
                          "division in msm.glsl lacks its guard (docs/numerics.md, the pivot "
                          "floors and the discriminant clamp).");
        if (range)
            out.push_back(std::to_string(range) + " hard cases give G outside [0, 1]: the final "
                          "clamp (or a pivot floor) looks missing.");
        if (monotone)
            out.push_back(std::to_string(monotone) + " hard cases are non-monotone in zf: look at "
                          "the root ordering and the case selection in msm.glsl.");
    }

    // final fails where the isolated stages pass: the stages' interface.
    std::set<std::string> interfaceScenes;
    for (const auto& t : s.tests) {
        // Only a final that rendered: one that timed out, crashed or was not run says nothing
        // of the interface.
        if (t.stage != "final" || !shown(t.hidden) || !t.lostPoints() || t.notImplemented() ||
            t.images.empty())
            continue;
        bool othersPass = true, any = false;
        for (const auto& u : s.tests)
            if (u.scene == t.scene && u.stage != "final") any = true, othersPass = othersPass && !u.lostPoints();
        if (any && othersPass) interfaceScenes.insert(t.scene);
    }
    if (!interfaceScenes.empty())
        out.push_back("final loses points on " + list(interfaceScenes) + " while every isolated "
                      "stage of that scene passes: look at what the stages share (relativeDepth, "
                      "used by the lighting pass on depths outside the shadow pass's range).");
    return out;
}

}  // namespace sl::grader
