// worker: the render a child process does for one (scene, stage) pair. Stage isolation is
// a ShaderLibrary whose stage map points the graded stage's files at the submission and every
// other stage file at reference/:
//   moments   shadow passes only, student moments.glsl            -> moments_raw
//   gaussian  student blur on the reference moments (from a file)  -> moments_filtered
//   sat       student sat.comp + sat_lookup.glsl on the same input  -> moments_filtered
//   msm       student msm.glsl, lighting only, from the reference's
//             filtered moments (a file)                           -> shadow
//   robustness student msm.glsl on the hard-case catalogue (no scene) -> worker.json
//   final     the whole submission                                 -> final
//   reference the whole reference solution                         -> all of the above
// The images go out as .raw (raw_image.h). The filter stages read their input from a file, so they are isolated with goldens alone.
#include "worker.h"

#include "grader.h"

#include "cli_exit_codes.h"
#include "depth_ladder.h"
#include "gl_context.h"
#include "msm_robustness.h"
#include "pass_plan.h"
#include "probe.h"
#include "paths.h"
#include "raw_image.h"
#include "renderer.h"
#include "scene.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <iostream>

namespace sl::grader {
namespace {

ShaderLibrary makeLibrary(const WorkerArgs& a) {
    const fs::path sub = a.submission;
    const fs::path other = a.reference.empty() ? sub : fs::path(a.reference);
    std::map<std::string, fs::path> mine;
    if (a.stage == "final")
        for (const auto& name : stageFileNames()) mine[name] = sub;
    else if (a.stage != "reference")
        for (const auto& name : stageFiles(a.stage, "")) mine[name] = sub;
    // Student paths show as "submission/msm.glsl:42".
    return ShaderLibrary::mixed(other, mine, repoRoot(), sub.parent_path());
}

}  // namespace

RenderResult renderFromMoments(Renderer& renderer, Scene scene, const Image& filtered) {
    scene.shadow.filter = FilterKind::None;
    const PassPlan plan = planPasses(scene);
    RenderInputs inputs;
    if (!plan.shadowLights.empty()) inputs.filteredMoments[plan.shadowLights.front()] = filtered;
    return renderer.render(scene, plan, inputs);
}

void runWorker(const WorkerArgs& a) {
    // Test hook (tests/test_grader_limits.cpp): make this stage's worker crash.
    if (const char* fault = std::getenv("SHADOWLAB_GRADER_FAULT"); fault && a.stage == fault)
        std::raise(SIGSEGV);
    Scene scene = loadScene(a.scene);
    auto context = createContext(parseBackendKind(a.backend));
    if (a.stage == "robustness") {
        // The catalogue with the reference's α; the scene only names the GL settings.
        RobustnessReport report = probeMsmRobustness(makeLibrary(a));
        bool stub = !report.cases.empty();
        for (const auto& c : report.cases) stub = stub && c.G == -1.0f;
        nlohmann::json failing = nlohmann::json::array();
        for (const auto& c : report.cases)
            if (!c.ok() && failing.size() < 50)
                failing.push_back({{"case", c.input.name},
                                   {"b", {c.input.b.x, c.input.b.y, c.input.b.z, c.input.b.w}},
                                   {"zf", c.input.zf},
                                   {"G", std::isfinite(c.G) ? nlohmann::json(c.G) : nlohmann::json(std::to_string(c.G))},
                                   {"problems", c.problems()}});
        fs::create_directories(a.out);
        const ContextInfo& info = context->info();
        nlohmann::json j = {{"stage", a.stage},
                            {"images", nlohmann::json::array()},
                            {"stubNotes", stub ? std::vector<std::string>{"submission/msm.glsl: "
                                                 "momentShadowIntensity: not implemented yet "
                                                 "(it returns the stub value -1)"}
                                               : std::vector<std::string>{}},
                            {"robustness", {{"score", report.score},
                                            {"cases", report.cases.size()},
                                            {"failed", report.failed},
                                            {"failing", failing},
                                            {"summary", report.summary(20)}}},
                            {"backend", info.backend},
                            {"renderer", info.renderer},
                            {"mesaVersion", info.mesaVersion}};
        std::ofstream(fs::path(a.out) / "worker.json") << j.dump(2) << "\n";
        return;
    }
    Renderer renderer(makeLibrary(a));
    RenderResult result;
    std::vector<std::string> wanted;
    if (a.stage == "gaussian" || a.stage == "sat") {
        // The building blocks on the reference moments; first shadowing light only.
        Image input = readAnyImage(a.input);
        Texture src = Texture::create(input.width, input.height, GL_RGBA32F);
        const bool sat = a.stage == "sat";  // sat.comp's table: two texels per entry
        Texture scratch = Texture::create(sat ? satTableWidth(input.width) : input.width,
                                          input.height, GL_RGBA32F);
        Texture dst = Texture::create(input.width, input.height, GL_RGBA32F);
        src.upload(input);
        const ShadowEffect& fx = scene.shadow;
        if (a.stage == "gaussian") {
            renderer.gaussianPass(src, scratch, fx.gaussianRadius, fx.gaussianSigma, {1, 0});
            renderer.gaussianPass(scratch, dst, fx.gaussianRadius, fx.gaussianSigma, {0, 1});
        } else {
            Texture table = Texture::create(satTableWidth(input.width), input.height,
                                            GL_RGBA32F);
            renderer.satPass(src, scratch, {1, 0});
            renderer.satPass(scratch, table, {0, 1});
            renderer.satResolvePass(table, dst, fx.satKernelTexels);
        }
        gl::Finish();
        result.images["moments_filtered"] = dst.read();
    } else if (a.stage == "msm") {
        // Lighting only, from the reference's filtered moments (a file: isolated with the
        // goldens alone), sampled bilinearly whatever the scene's filter.
        result = renderFromMoments(renderer, scene, readAnyImage(a.input));
    } else {
        PassPlan plan;
        if (a.stage == "moments") {
            // Only the shadow passes: nothing else compiles, so only moments.glsl can fail.
            scene.shadow.filter = FilterKind::None;
            plan = planPasses(scene);
            std::erase_if(plan.passes,
                          [](const PlannedPass& p) { return p.kind != PassKind::Shadow; });
        } else {
            plan = planPasses(scene);
        }
        result = renderer.render(scene, plan);
        if (a.stage == "moments")  // relativeDepth outside [near, far] too (depth_ladder.h)
            result.images[kDepthLadderImage] =
                depthLadderImage(probeMoments(makeLibrary(a), relativeDepthLadder()));
        if (a.stage == "reference") {
            // What the msm stage is compared with: the same lighting-only render, from these
            // filtered moments, saved as "msm_<image>".
            RenderResult isolated =
                renderFromMoments(renderer, scene, result.images.at("moments_filtered"));
            for (auto& [name, image] : isolated.images)
                if (name.rfind("shadow", 0) == 0) result.images["msm_" + name] = std::move(image);
        }
    }
    const std::string prefix = a.stage == "reference" ? "" : stageImage(a.stage);
    fs::create_directories(a.out);
    nlohmann::json written = nlohmann::json::array();
    for (const auto& [name, image] : result.images) {
        if (name.rfind("sat", 0) == 0) continue;  // the table itself is never compared
        if (!prefix.empty() && name.rfind(prefix, 0) != 0) continue;
        writeRaw(image, fs::path(a.out) / (name + ".raw"));
        written.push_back(name);
    }
    // The stage is the stub everywhere (the grader then skips its renders of the other scenes,
    // grade.cpp): a filter's whole output is -1; computeMoments gave -1 on every rung of the
    // depth ladder (the map's background keeps its clear value, so the map cannot tell).
    bool stubEverywhere = false;
    const std::string shown = a.stage == "moments" ? kDepthLadderImage : stageImage(a.stage);
    if (a.stage == "moments" || a.stage == "gaussian" || a.stage == "sat")
        if (auto it = result.images.find(shown); it != result.images.end())
            stubEverywhere = it->second.allStub();
    const ContextInfo& info = context->info();
    nlohmann::json j = {{"stage", a.stage},
                        {"scene", scene.name},
                        {"stubEverywhere", stubEverywhere},
                        {"images", written},
                        {"stubNotes", result.stubNotes},
                        {"backend", info.backend},
                        {"renderer", info.renderer},
                        {"mesaVersion", info.mesaVersion}};
    std::ofstream(fs::path(a.out) / "worker.json") << j.dump(2) << "\n";
}

int workerMain(const WorkerArgs& a) {
    // The same messages and codes as main() gives an exec'd grade-worker (framework/cli/main.cpp).
    try {
        runWorker(a);
        return cli::Ok;
    } catch (const SceneError& e) {
        std::cerr << "scene error: " << e.what() << "\n";
        return cli::BadInput;
    } catch (const ShaderError& e) {
        std::cerr << "shader error:\n" << e.what() << "\n";
        return cli::ShaderFailed;
    } catch (const BackendError& e) {
        std::cerr << "no OpenGL: " << e.what() << "\n";
        return cli::NoBackend;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return cli::Failed;
    } catch (...) {
        std::cerr << "error: unknown\n";
        return cli::Failed;
    }
}

}  // namespace sl::grader
