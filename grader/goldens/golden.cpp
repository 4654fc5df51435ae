// golden: making, reading and checking golden images, encoded as golden_encoding.h says.
// The manifest lists each file's SHA-256 and its pixels' (`golden --check` compares pixels:
// golden_check.h). Beside each EXR, a PNG preview (<image>.png) for people to look at.
// Hidden scenes' goldens go into goldens/ next to their scene file, never the public folder.
#include "golden.h"
#include "golden_encoding.h"
#include "graded_reference.h"
#include "image_name.h"
#include "golden_check.h"
#include "raw_image.h"
#include "report.h"
#include "worker.h"

#include "grader.h"
#include "gl_context.h"
#include "image_io.h"
#include "pass_plan.h"
#include "paths.h"
#include "renderer.h"
#include "sat_kernel_ladder.h"
#include "scene.h"
#include "scene_list.h"
#include "scene_size.h"
#include "probe_check.h"
#include "technique.h"

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <set>

namespace sl::grader {
namespace {

// `image` is rounded already (gradedReferenceImages): the Half file holds its values exactly.
void writeEncoded(const Image& image, const fs::path& path, const std::string& name) {
    writeExr(image, path, storedAsMoments(name) ? SampleType::Float : SampleType::Half);
}

// The golden `exr` just written, and its PNG preview beside it (<image>.png: the stored values
// as render's PNGs show them, colour sRGB-encoded, at most 512 texels wide: the report's
// preview): both into the manifest entry's "images" and "previews".
void writeGolden(const Image& pixels, const fs::path& dir, const std::string& scene,
                 const std::string& image, nlohmann::json& images, nlohmann::json& previews) {
    const fs::path exr = dir / (image + ".exr"), png = dir / (image + ".png");
    writeEncoded(pixels, exr, image);
    const Image stored = readAnyImage(exr);
    images[image] = nlohmann::json{{"file", scene + "/" + image + ".exr"},
                                   {"sha256", sha256File(exr)},
                                   {"pixels_sha256", sha256Pixels(stored)}};
    writePngPreview(image == kSatKernelImage ? satKernelPreview(stored, satKernelLargest(stored))
                                             : previewImage(stored),
                    png, isImage(image, ImageKind::Final));
    previews[image] = nlohmann::json{{"file", scene + "/" + image + ".png"},
                                     {"sha256", sha256File(png)},
                                     {"pixels_sha256", sha256Pixels(readImage(png))}};
}

std::string envOr(const char* name, const char* fallback) {
    const char* v = std::getenv(name);
    return v ? v : fallback;
}

std::string joined(const std::vector<std::string>& items, const char* sep) {
    std::string s;
    for (const auto& i : items) s += (s.empty() ? "" : sep) + i;
    return s;
}

// The ladder's rows whose own files solve a stage (TechniqueRow::solvesStage) are left out of
// the student kit; their final images at the demo's sheet width stand in for them on its
// comparison sheets (`compare`), as dir/ladder/<technique>.png.
void renderLadderStandIns(const Scene& full, Renderer& renderer, const fs::path& dir) {
    for (const TechniqueRow& row : techniqueTable()) {
        if (row.solvesStage.empty()) continue;
        Scene scene = full;
        scaleScene(scene, kSheetImageWidth);
        overrideTechnique(scene.shadow, row.id);
        const RenderResult result = renderer.render(scene, planPasses(scene));
        fs::create_directories(dir / "ladder");
        writePngPreview(result.images.at("final"), dir / "ladder" / (row.name + ".png"), true);
    }
}

// Renders one scene, checks its probes, and encodes its goldens into `dir` (an empty folder);
// with `standIns`, also the ladder's stand-ins of a public scene. Returns the manifest entry.
nlohmann::json renderScene(const GradedScene& gs, const fs::path& solution, const fs::path& dir,
                           const ContextInfo& info, std::vector<std::string>& probeErrors,
                           bool standIns) {
    const Scene& scene = *gs.scene;
    Renderer renderer(ShaderLibrary::forSolution(solution, repoRoot()));
    RenderResult full;
    const RenderResult graded = gradedReferenceImages(renderer, scene, &full);
    const auto failures = probeFailures(scene, [&](const std::string& name) -> const Image* {
        auto it = full.images.find(name);
        return it == full.images.end() ? nullptr : &it->second;
    });
    probeErrors.insert(probeErrors.end(), failures.begin(), failures.end());
    if (!failures.empty()) return nullptr;
    fs::create_directories(dir);
    const std::string& name = gs.name;
    nlohmann::json images = nlohmann::json::object(), previews = nlohmann::json::object();
    for (const auto& [image, pixels] : graded.images) writeGolden(pixels, dir, name, image, images, previews);
    nlohmann::json entry = {{"scene_sha256", sha256File(gs.path)},
                            {"images", images},
                            {"previews", previews},
                            {"mesa_version", info.mesaVersion},
                            {"renderer", info.renderer}};
    if (gs.hidden) entry["scene_file"] = fs::absolute(gs.path).lexically_normal().string();
    else if (standIns) renderLadderStandIns(scene, renderer, dir);
    std::cerr << "golden: " << name << " (" << images.size() << " images)\n";
    return entry;
}

}  // namespace

fs::path goldenFolder(const GradedScene& scene, const fs::path& publicGoldens) {
    return scene.hidden ? fs::absolute(scene.path).parent_path() / "goldens" : publicGoldens;
}

GoldenRun runGoldens(const GoldenOptions& o) {
    const fs::path solution = resolveSolution(o.solution);
    auto context = createContext(parseBackendKind(o.backend));
    const ContextInfo& info = context->info();
    const auto scenes = gradedScenes(o.scenes);
    const fs::path staging = fs::temp_directory_path() /
                             ("shadowlab-golden-" + std::to_string(::getpid()));
    std::error_code ec;
    fs::remove_all(staging, ec);

    // Render everything into a staging folder first: a wrong probe leaves every golden as it was.
    std::map<fs::path, std::vector<std::pair<GradedScene, nlohmann::json>>> byFolder;
    std::vector<std::string> probeErrors;
    for (const GradedScene& gs : scenes) {
        const fs::path folder = goldenFolder(gs, o.out);
        nlohmann::json entry =
            renderScene(gs, solution, staging / gs.name, info, probeErrors, !o.check);
        if (!entry.is_null()) byFolder[folder].push_back({gs, entry});
    }
    if (!probeErrors.empty()) {
        fs::remove_all(staging, ec);
        throw SceneError("the " + o.solution + " render does not match " +
                         std::to_string(probeErrors.size()) + " probe(s) (nothing was written):\n" +
                         joined(probeErrors, "\n"));
    }

    GoldenRun run;
    std::vector<std::string> staleScenes;  // as --scenes would name them
    bool stalePublic = false;              // --out concerns public scenes only
    for (const auto& [folder, entries] : byFolder) {
        nlohmann::json manifest = readManifest(folder);
        if (!manifest.is_object()) manifest = nlohmann::json::object();
        if (!manifest.contains("scenes") || !manifest["scenes"].is_object())
            manifest["scenes"] = nlohmann::json::object();
        std::set<std::string> rendered;
        for (const auto& [gs, entry] : entries) rendered.insert(gs.name);
        const bool publicFolder = fs::weakly_canonical(folder) == fs::weakly_canonical(o.out);
        // Entries this run does not render: kept, and said so; dropped only when their
        // images are gone; a public folder's entry for a scene students lack is a leak.
        std::vector<std::string> kept, dropped;
        for (auto it = manifest["scenes"].begin(); it != manifest["scenes"].end();) {
            const std::string name = it.key();
            if (rendered.count(name)) { ++it; continue; }
            if (!fs::exists(folder / name)) {
                dropped.push_back(name);
                it = manifest["scenes"].erase(it);
                continue;
            }
            kept.push_back(name);
            if (publicFolder && !fs::exists(repoRoot() / "scenes" / (name + ".json"))) {
                run.messages.push_back(
                    "warning: " + (folder / name).string() + " holds goldens of \"" + name +
                    "\", which is not a public scene: they ship in the student kit. If it is a "
                    "hidden scene, delete that folder (its goldens belong in goldens/ next to its "
                    "scene file: golden --scenes <path>); the manifest entry goes with it");
                if (o.check) run.stale.push_back(name + ": not a public scene, in the public goldens");
            }
            ++it;
        }
        if (o.check) {
            const bool sameRenderer = manifest.value("mesa_version", "") == info.mesaVersion &&
                                      manifest.value("renderer", "") == info.renderer;
            if (!sameRenderer)
                run.messages.push_back("the goldens in " + folder.string() + " were made on \"" +
                                       manifest.value("renderer", "?") + "\", Mesa " +
                                       manifest.value("mesa_version", "?") + "; this is \"" +
                                       info.renderer + "\", Mesa " + info.mesaVersion +
                                       ": images are checked against the grading tolerance");
            for (const auto& [gs, entry] : entries) {
                GoldenVerdicts v;
                checkGoldenEntry(gs.name, entry, staging / gs.name, manifest, folder / gs.name,
                                 sameRenderer, v);
                run.stale.insert(run.stale.end(), v.stale.begin(), v.stale.end());
                for (const auto& n : v.notes) run.messages.push_back("within tolerance: " + n);
                if (!v.stale.empty()) {
                    staleScenes.push_back(gs.hidden ? gs.path.string() : gs.name);
                    stalePublic = stalePublic || !gs.hidden;
                }
            }
            continue;
        }
        for (const auto& [gs, entry] : entries) {
            fs::remove_all(folder / gs.name, ec);
            fs::create_directories(folder / gs.name);
            fs::copy(staging / gs.name, folder / gs.name, fs::copy_options::recursive);
            manifest["scenes"][gs.name] = entry;
        }
        std::string madeBy = "shadowlab golden --solution " + o.solution + " --out " + o.out.string();
        if (!o.scenes.empty()) madeBy += " --scenes " + joined(o.scenes, ",");
        manifest["mesa_version"] = info.mesaVersion;
        manifest["renderer"] = info.renderer;
        manifest["gl_version"] = info.version;
        manifest["backend"] = info.backend;
        manifest["image_library"] = "OpenImageIO " + imageLibraryVersion();
        manifest["settings"] = {
            {"LP_NUM_THREADS", envOr("LP_NUM_THREADS", "")},
            {"GALLIUM_DRIVER", envOr("GALLIUM_DRIVER", "llvmpipe")},
            {"moment_encoding",
             "float32, mantissa rounded to " + std::to_string(kMomentMantissaBits) + " bits, ZIP"},
            {"image_encoding", "half, ZIP"},
            {"preview_encoding", "PNG beside each EXR, 8-bit, at most 512 texels wide, colour sRGB"}};
        manifest["solution"] = o.solution;
        manifest["made_by"] = madeBy;
        fs::create_directories(folder);
        std::ofstream(folder / "manifest.json") << manifest.dump(2) << "\n";
        std::string line = "wrote " + (folder / "manifest.json").string() + " (" +
                            std::to_string(entries.size()) + " scenes rendered";
        if (!kept.empty()) line += "; kept from before: " + joined(kept, ", ");
        if (!dropped.empty()) line += "; dropped, their images are gone: " + joined(dropped, ", ");
        run.messages.push_back(line + ")");
    }
    fs::remove_all(staging, ec);
    if (!run.stale.empty()) {
        run.advice = "shadowlab golden --solution " + o.solution;
        if (stalePublic) run.advice += " --out " + o.out.string();
        if (!staleScenes.empty()) run.advice += " --scenes " + joined(staleScenes, ",");
    }
    return run;
}

void checkReferenceProbes(const std::vector<GradedScene>& scenes,
                          const std::function<fs::path(size_t, const std::string&)>& file) {
    std::vector<std::string> errors;
    int hidden = 0;
    for (size_t i = 0; i < scenes.size(); ++i) {
        const Scene& scene = *scenes[i].scene;
        std::map<std::string, Image> images;
        bool missing = false;
        for (const ShadowProbe& p : scene.probes) {
            const std::string name = probeImageName(scene, p);
            if (images.count(name)) continue;
            const fs::path f = file(i, name);
            if (!fs::exists(f)) { missing = true; break; }
            images[name] = readAnyImage(f);
        }
        if (missing) continue;
        const auto failures = probeFailures(scene, [&](const std::string& name) -> const Image* {
            auto it = images.find(name);
            return it == images.end() ? nullptr : &it->second;
        });
        if (scenes[i].hidden) hidden += int(failures.size());
        else errors.insert(errors.end(), failures.begin(), failures.end());
    }
    if (hidden)
        errors.push_back(std::to_string(hidden) + " probe(s) of hidden scenes (see them with: "
                         "shadowlab golden --check --scenes <the hidden scene files>)");
    if (!errors.empty())
        throw std::runtime_error("the reference does not match the scenes' probes, so the scenes "
                                 "(or their probes) are wrong:\n" + joined(errors, "\n"));
}

nlohmann::json readManifest(const fs::path& goldens) {
    std::ifstream in(goldens / "manifest.json");
    if (!in) return nullptr;
    try {
        return nlohmann::json::parse(in);
    } catch (const std::exception&) {
        return nullptr;
    }
}

std::vector<std::string> manifestWarnings(const nlohmann::json& manifest,
                                          const nlohmann::json& running) {
    std::vector<std::string> w;
    if (manifest.is_null()) return {"golden manifest missing or unreadable"};
    auto field = [](const nlohmann::json& j, const char* k) {
        return j.contains(k) && j[k].is_string() ? j[k].get<std::string>() : std::string();
    };
    for (auto [key, label] : {std::pair{"mesaVersion", "mesa_version"},
                              std::pair{"renderer", "renderer"}}) {
        const std::string now = field(running, key), then = field(manifest, label);
        if (!now.empty() && now != then)
            w.push_back(std::string("goldens were made with ") + label + " \"" + then +
                        "\", this machine has \"" + now +
                        "\": small edge differences are forgiven, larger ones may cost points");
    }
    return w;
}

}  // namespace sl::grader
