// golden_check: see golden_check.h.
#include "golden_check.h"
#include "image_name.h"
#include "metrics.h"
#include "rubric.h"

#include "image_io.h"

#include <cstdio>

namespace sl::grader {

namespace fs = std::filesystem;

std::string goldenImageStage(const std::string& image) {
    const auto n = ImageName::parse(image);
    const bool plain = n && !n->msmIsolated;
    if (image == ImageName{.kind = ImageKind::MomentsRaw}.str()) return "moments";
    if (plain && n->kind == ImageKind::RelativeDepth) return "moments";  // zf: the moments' rule
    if (plain && n->moments()) return "gaussian";  // the sat stage has the same rule
    if (plain && n->colour()) return "final";
    return "msm";  // shadow, shadow_overhead, msm_shadow...
}

namespace {

std::string percentWithDecimals(double fraction) {
    char s[32];
    std::snprintf(s, sizeof s, "%.3f %%", 100.0 * fraction);
    return s;
}

// Full marks under the default rubric's rule for the image's stage, or why not.
std::string outsideTolerance(const std::string& image, const Image& fresh, const Image& golden) {
    static const Rubric rubric = defaultRubric();
    const std::string stage = goldenImageStage(image);
    Comparison c;
    if (stage == "moments") c = compareMoments(fresh, golden, rubric.momentsAbs, rubric.momentsRel);
    else if (stage == "gaussian") c = compareMoments(fresh, golden, rubric.filterAbs, rubric.filterRel);
    else c = compareImages(fresh, golden, stage == "final" ? rubric.finalTol : rubric.shadowTol);
    if (!c.error.empty()) return c.error;
    const double pass = rubric.ramp(stage).first;
    if (c.fraction < pass)
        return percentWithDecimals(c.fraction) + " of the texels within the " + stage + " tolerance (full marks need " +
               percentWithDecimals(pass) + ")";
    if ((stage == "moments" || stage == "gaussian") && c.worst > rubric.worstTexelFactor)
        return "a texel is " + std::to_string(c.worst) + "x the " + stage + " tolerance off";
    return "";
}

}  // namespace

void checkGoldenEntry(const std::string& scene, const nlohmann::json& fresh,
                      const fs::path& freshDir, const nlohmann::json& committed,
                      const fs::path& committedDir, bool sameRenderer, GoldenVerdicts& v) {
    const auto& scenes = committed.is_object() && committed.contains("scenes")
                             ? committed["scenes"] : nlohmann::json::object();
    if (!scenes.contains(scene)) {
        v.stale.push_back(scene + ": no goldens in the manifest");
        return;
    }
    const auto& old = scenes[scene];
    if (old.value("scene_sha256", "") != fresh["scene_sha256"].get<std::string>())
        v.stale.push_back(scene + ": the scene file changed since its goldens were made");
    auto pixelsOf = [](const nlohmann::json& e) {
        return e.is_object() ? e.value("pixels_sha256", std::string()) : std::string();
    };
    for (const auto& [image, e] : fresh["images"].items()) {
        const std::string name = scene + "/" + image;
        if (!old["images"].contains(image)) { v.stale.push_back(name + ": not in the manifest"); continue; }
        const std::string want = pixelsOf(old["images"][image]);
        if (want.empty()) { v.stale.push_back(name + ": the manifest has no pixel hash"); continue; }
        if (want == pixelsOf(e)) continue;
        if (sameRenderer) { v.stale.push_back(name); continue; }
        const fs::path committedFile = committedDir / (image + ".exr");
        if (!fs::exists(committedFile)) { v.stale.push_back(name + ": " + committedFile.string() + " is missing"); continue; }
        const Image golden = readImage(committedFile);
        if (sha256Pixels(golden) != want) {
            v.stale.push_back(name + ": " + committedFile.string() + " is not the file the manifest lists");
            continue;
        }
        const std::string why = outsideTolerance(image, readImage(freshDir / (image + ".exr")), golden);
        const std::string rule = image == "moments_filtered" ? "filter" : goldenImageStage(image);
        if (why.empty()) v.notes.push_back(name + ": other pixels on this renderer, within the " +
                                           rule + " tolerance");
        else v.stale.push_back(name + ": " + why);
    }
    for (const auto& [image, e] : old["images"].items())
        if (!fresh["images"].contains(image))
            v.stale.push_back(scene + "/" + image + ": in the manifest, no longer rendered");
    // A preview shows its image: on the goldens' renderer its pixels are checked like the
    // image's; elsewhere it follows the image's verdict.
    const auto& oldPreviews = old.contains("previews") ? old["previews"] : nlohmann::json::object();
    for (const auto& [image, e] : fresh["previews"].items()) {
        if (!oldPreviews.contains(image)) v.stale.push_back(scene + "/" + image + ".png: no preview in the manifest");
        else if (sameRenderer && pixelsOf(oldPreviews[image]) != pixelsOf(e))
            v.stale.push_back(scene + "/" + image + ".png");
    }
}

}  // namespace sl::grader
