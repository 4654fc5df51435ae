// cli_study: the ground truth and the accuracy study (docs/accuracy.md).
//   truth  renders a scene and writes truth.exr (ray-traced, Embree) and filtered_truth.exr
//          (the exact same-kernel PCF of its shadow map) next to the render
//   study  sweeps techniques × map sizes × filters × radii into DIR/study.csv, plots, index.html
#include "cli_commands.h"
#include "filtered_truth.h"
#include "gl_context.h"
#include "image_io.h"
#include "light_reach.h"
#include "pass_plan.h"
#include "paths.h"
#include "render_output.h"
#include "renderer.h"
#include "scene.h"
#include "scene_truth.h"
#include "study.h"
#include "study_shard.h"
#include "technique.h"

#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <thread>

namespace sl::cli {
namespace {

// "Intel(R) Xeon(R) ... (2 cores), llvmpipe (LLVM 15.0.6, 256 bits), Mesa 22.3.6".
std::string machineLine(const ContextInfo& info) {
    std::ifstream cpu("/proc/cpuinfo");
    std::string line, model = "unknown CPU";
    while (std::getline(cpu, line))
        if (line.rfind("model name", 0) == 0) {
            model = line.substr(line.find(':') + 2);
            break;
        }
    return model + " (" + std::to_string(std::thread::hardware_concurrency()) + " threads), " +
           info.renderer + ", Mesa " + info.mesaVersion + " (" + info.backend + ")";
}

int runTruth(const std::string& scenePath, const std::string& outDir, int samples,
             const std::string& cache, const std::string& backend) {
    Scene scene = loadScene(scenePath);
    auto context = createContext(parseBackendKind(backend));
    const std::string solution = defaultSolution();
    const ShaderLibrary lib = ShaderLibrary::forSolution(resolveSolution(solution), repoRoot());
    const PassPlan plan = planPasses(scene);
    Renderer renderer(lib);
    RenderResult result = renderer.render(scene, plan);
    writeRenderOutputs(scene, plan, result, {solution, context->info()}, outDir);
    SceneTruthOptions o;
    o.rays.samples = samples;
    o.cacheDir = cache == "none" ? fs::path() : cache.empty() ? defaultTruthCache() : fs::path(cache);
    const SceneTruth truth = computeSceneTruth(scene, lib, o);
    writeTruthFiles(truth, outDir);
    // The filtered truth of the scene's map size and kernel. The depth map is msm4's shadow pass
    // (b1 = z; other techniques store warped or quantised values), as the study's.
    const int light = truth.ray.light;
    Scene depthScene = scene;
    overrideTechnique(depthScene.shadow, techniqueFromName("msm4"));
    depthScene.shadow.filter = FilterKind::None;
    const PassPlan depthPlan = planPasses(depthScene);
    const RenderResult depthRender = renderer.render(depthScene, depthPlan);
    const std::string suffix =
        light == depthPlan.shadowLights.front() ? "" : "_light" + std::to_string(light);
    const Image& raw = depthRender.images.at("moments_raw" + suffix);
    Image depth(raw.width, raw.height, 1);
    for (size_t i = 0, n = size_t(raw.width) * raw.height; i < n; ++i)
        depth.pixels[i] = raw.pixels[i * size_t(raw.channels)];
    const Image filtered = filteredTruth(scene, truth.points, truth.ray.reached, light, depth,
                                         kernelOf(scene.shadow));
    writeExr(filtered, fs::path(outDir) / "filtered_truth.exr");
    writePngPreview(filtered, fs::path(outDir) / "filtered_truth.png", false);
    nlohmann::json j = {{"scene", scene.path}, {"hash", truth.hash}, {"fromCache", truth.fromCache},
                        {"light", light}, {"samplesPerPixel", truth.ray.samplesPerPixel},
                        {"maxStdError", truth.ray.maxStdError}, {"seconds", truth.seconds},
                        {"machine", machineLine(context->info())}};
    std::ofstream(fs::path(outDir) / "truth.json") << j.dump(2) << "\n";
    std::cout << "wrote " << outDir << "/{truth,filtered_truth}.{exr,png} and truth.json: light "
              << light << ", " << truth.ray.samplesPerPixel << " ray(s) per pixel, max standard "
              << "error " << truth.ray.maxStdError << ", "
              << (truth.fromCache ? "from the cache" : "traced") << " in " << truth.seconds
              << " s (key " << truth.hash.substr(0, 12) << ")\n";
    return Ok;
}

std::vector<std::string> splitList(const std::string& s) {
    std::vector<std::string> out;
    size_t start = 0;
    for (size_t i = 0; i <= s.size(); ++i)
        if (i == s.size() || s[i] == ',') {
            if (i > start) out.push_back(s.substr(start, i - start));
            start = i + 1;
        }
    return out;
}

std::vector<int> intList(const std::string& s, const std::string& option) {
    std::vector<int> out;
    for (const auto& item : splitList(s)) {
        try {
            size_t used = 0;
            out.push_back(std::stoi(item, &used));
            if (used != item.size()) throw std::invalid_argument(item);
        } catch (const std::logic_error&) {
            throw CLI::ValidationError(option, "expected a comma-separated list of integers, found \"" + item + "\"");
        }
    }
    if (out.empty()) throw CLI::ValidationError(option, "expected at least one integer");
    return out;
}

}  // namespace

void addStudyCommands(CLI::App& app, Context& ctx) {
    auto* truth = app.add_subcommand("truth", "render a scene and its ground truths (Embree)");
    struct TruthArgs { std::string scene, out = "out", cache; int samples = 1296; };
    auto t = std::make_shared<TruthArgs>();
    truth->add_option("--scene", t->scene, "scene JSON file")->required();
    truth->add_option("--out", t->out, "output folder (the render and the truths)");
    truth->add_option("--samples", t->samples, "shadow rays per pixel for area lights (an even square)")
        ->check(CLI::Range(4, 65536));
    truth->add_option("--cache", t->cache, "truth cache folder, or 'none' (default ~/.cache/shadowlab/truth)");
    truth->callback([t, &ctx] { ctx.exitCode = runTruth(t->scene, t->out, t->samples, t->cache, ctx.backend); });

    auto* study = app.add_subcommand("study", "sweep techniques, map sizes and filters against the ground truth");
    struct StudyArgs {
        std::string scene, techniques, sizes = "256,512,1024,2048", radii = "1,2,4,8,16",
                    filters = "gaussian,sat", solution = defaultSolution(), out, cache,
                    lightSizes, shard = "1/1";
        std::vector<std::string> merge;
        int repeats = 3, samples = 1296, image = 0, flicker = 0;
        double flickerStep = 0.2;
        bool explain = false, noProgress = false, noShare = false;
    };
    auto s = std::make_shared<StudyArgs>();
    study->add_option("--scene", s->scene, "scene JSON file")->required();
    study->add_option("--techniques", s->techniques,
                      "comma-separated technique specs (vsm:bleedReduction=0.3); default: every technique");
    study->add_option("--map-sizes", s->sizes, "shadow-map sizes");
    study->add_option("--radii", s->radii, "Gaussian radii r, σ = r / 2 (the SAT box has the same variance: r·√3 texels)");
    study->add_option("--filters", s->filters, "filters to sweep where a technique allows them");
    study->add_option("--light-sizes", s->lightSizes,
                      "light sizes to sweep (0: point light; > 0: a disk that wide); default: the scene's");
    study->add_option("--repeats", s->repeats, "timed frames per row")->check(CLI::Range(1, 100));
    study->add_option("--flicker", s->flicker,
                      "temporal stability: frames of a turning light per row (0: not measured)")
        ->check(CLI::Range(0, 64));
    study->add_option("--flicker-step", s->flickerStep, "degrees the light turns per frame")
        ->check(CLI::Range(0.001, 30.0));
    study->add_option("--shard", s->shard, "run only shard K of N (K/N), whole groups of rows sharing a map");
    study->add_option("--merge", s->merge, "study folders of shards to merge into --out first")
        ->expected(1, -1);
    study->add_option("--solution", s->solution, "whose stages: reference, student or a folder");
    study->add_option("--samples", s->samples, "shadow rays per pixel for area lights")->check(CLI::Range(4, 65536));
    study->add_option("--image", s->image, "render the main camera at N×N instead")->check(CLI::Range(16, 4096));
    study->add_option("--cache", s->cache, "truth cache folder, or 'none'");
    study->add_option("--out", s->out, "output folder (resumes the study.csv found there)")->required();
    study->add_flag("--explain", s->explain, "print each row's plan, times and what it reused");
    study->add_flag("--no-progress", s->noProgress, "no progress bar");
    study->add_flag("--no-share", s->noShare,
                    "every row renders its own shadow map (default: rows whose shadow pass would "
                    "draw the same map share one, rendered once)");
    study->callback([s, &ctx] {
        StudyOptions o;
        o.scene = s->scene;
        o.techniques = s->techniques.empty() ? allTechniqueSpecs() : splitList(s->techniques);
        o.mapSizes = intList(s->sizes, "--map-sizes");
        o.radii = intList(s->radii, "--radii");
        o.filters = splitList(s->filters);
        o.repeats = s->repeats;
        o.flickerFrames = s->flicker;
        o.flickerStep = s->flickerStep;
        for (const auto& item : splitList(s->lightSizes)) {
            try {
                size_t used = 0;
                const double v = std::stod(item, &used);
                if (used != item.size() || v < 0) throw std::invalid_argument(item);
                o.lightSizes.push_back(v);
            } catch (const std::logic_error&) {
                throw CLI::ValidationError("--light-sizes", "expected sizes >= 0, found \"" + item + "\"");
            }
        }
        try {
            parseShard(s->shard, o.shard, o.shards);
        } catch (const std::invalid_argument& e) {
            throw CLI::ValidationError("--shard", e.what());
        }
        for (const auto& m : s->merge) o.mergeFrom.push_back(m);
        o.solution = s->solution;
        o.samples = s->samples;
        o.imageSize = s->image;
        o.out = s->out;
        o.cacheDir = s->cache == "none" ? fs::path() : s->cache.empty() ? defaultTruthCache() : fs::path(s->cache);
        o.explain = s->explain;
        o.progress = !s->noProgress;
        o.shareMaps = !s->noShare;
        auto context = createContext(parseBackendKind(ctx.backend));
        o.headline = machineLine(context->info());
        const StudySummary sum = runStudy(o, std::cout);
        std::cout << "study: " << sum.run << " row(s) run, " << sum.skipped
                  << " already in " << s->out << "/study.csv, " << sum.planned << " planned\n";
        for (const auto& n : sum.notes) std::cout << "  " << n << "\n";
        ctx.exitCode = Ok;
    });
}

}  // namespace sl::cli
