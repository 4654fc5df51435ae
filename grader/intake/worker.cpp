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
#include "image_name.h"

#include "grader.h"
#include "graded_reference.h"

#include "depth_ladder.h"
#include "sat_kernel_ladder.h"
#include "exit_codes.h"
#include "gl_context.h"
#include "msm_robustness.h"
#include "pass_plan.h"
#include "phase_clock.h"
#include "probe.h"
#include "paths.h"
#include "raw_image.h"
#include "renderer.h"
#include "scene.h"
#include "stub_survey.h"

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
    if (a.stage && a.stage->stage == Stage::Final)
        for (const auto& name : stageFileNames()) mine[name] = sub;
    else if (a.stage)
        for (const auto& name : a.stage->files) mine[name] = sub;
    // Student paths show as "submission/msm.glsl:42".
    return ShaderLibrary::mixed(other, mine, repoRoot(), sub.parent_path());
}

bool is(const WorkerArgs& a, Stage stage) { return a.stage && a.stage->stage == stage; }

// The submission's stage file a stub note names ("" if none): notes begin with the file's
// display path, "submission/<file>: ".
StubNote stubNote(const std::string& text) {
    for (const auto& f : stageFileNames())
        if (text.rfind("submission/" + f + ":", 0) == 0) return {f, text};
    return {"", text};
}

}  // namespace

nlohmann::json WorkerArgs::toJson() const {
    return {{"scene", scene},   {"stage", stage ? stage->name : "reference"},
            {"submission", submission}, {"reference", reference},
            {"input", input},   {"out", out}, {"backend", backend}};
}

WorkerArgs WorkerArgs::fromJson(const nlohmann::json& j) {
    WorkerArgs a;
    auto text = [&j](const char* key) {
        if (!j.is_object() || !j.contains(key) || !j[key].is_string())
            throw std::invalid_argument(std::string("worker arguments: no text \"") + key + "\"");
        return j[key].get<std::string>();
    };
    a.scene = text("scene");
    const std::string stage = text("stage");
    a.stage = stage == "reference" ? nullptr : &stageRow(stage);
    a.submission = text("submission");
    a.reference = text("reference");
    a.input = text("input");
    a.out = text("out");
    a.backend = text("backend");
    return a;
}

nlohmann::json WorkerResult::toJson() const {
    nlohmann::json notes = nlohmann::json::array();
    for (const auto& n : stubNotes) notes.push_back({{"file", n.file}, {"text", n.text}});
    nlohmann::json j = {{"stage", stage},         {"scene", scene},     {"stubEverywhere", stubEverywhere},
                        {"images", images},       {"stubNotes", notes}, {"backend", backend},
                        {"renderer", renderer},   {"mesaVersion", mesaVersion}};
    if (!robustness.is_null()) j["robustness"] = robustness;
    return j;
}

WorkerResult WorkerResult::fromJson(const nlohmann::json& j) {
    WorkerResult r;
    r.stage = j.value("stage", "");
    r.scene = j.value("scene", "");
    r.stubEverywhere = j.value("stubEverywhere", false);
    r.images = j.value("images", std::vector<std::string>{});
    for (const auto& n : j.value("stubNotes", nlohmann::json::array()))
        r.stubNotes.push_back({n.value("file", ""), n.value("text", "")});
    r.robustness = j.value("robustness", nlohmann::json());
    r.backend = j.value("backend", "");
    r.renderer = j.value("renderer", "");
    r.mesaVersion = j.value("mesaVersion", "");
    return r;
}

std::optional<WorkerResult> readWorkerResult(const fs::path& folder) {
    std::ifstream in(folder / kWorkerResultFile);
    if (!in) return std::nullopt;
    try {
        return WorkerResult::fromJson(nlohmann::json::parse(in));
    } catch (const std::exception&) {
        return std::nullopt;  // still being written
    }
}

void runWorker(const WorkerArgs& a) {
    // Test hook (tests/test_grader_limits.cpp): make this stage's worker crash.
    const std::string stageName = a.stage ? a.stage->name : "reference";
    if (const char* fault = std::getenv("SHADOWLAB_GRADER_FAULT"); fault && stageName == fault)
        std::raise(SIGSEGV);
    PhaseClock clock("worker");
    clock.lap("start (fork or exec)");
    Scene scene = loadScene(a.scene);
    auto context = createContext(parseBackendKind(a.backend));
    clock.lap("scene and GL context");
    WorkerResult out;
    out.stage = stageName;
    const ContextInfo& info = context->info();
    out.backend = info.backend, out.renderer = info.renderer, out.mesaVersion = info.mesaVersion;
    if (is(a, Stage::Robustness)) {
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
        if (stub)
            out.stubNotes.push_back(stubNote(stubNoteText("submission/msm.glsl",
                                                          StageFunction::MomentShadowIntensity)));
        out.robustness = {{"score", report.score},
                          {"cases", report.cases.size()},
                          {"failed", report.failed},
                          {"failing", failing},
                          {"summary", report.summary(20)}};
        std::ofstream(fs::path(a.out) / kWorkerResultFile) << out.toJson().dump(2) << "\n";
        clock.lap("the hard-case catalogue");
        return;
    }
    Renderer renderer(makeLibrary(a));
    RenderResult result;
    clock.lap("shader sources");
    std::vector<std::string> wanted;
    if (is(a, Stage::Gaussian) || is(a, Stage::Sat)) {
        // The building blocks on the reference moments; first shadowing light only.
        Image input = readAnyImage(a.input);
        Texture src = Texture::create(input.width, input.height, GL_RGBA32F);
        const bool sat = is(a, Stage::Sat);  // sat.comp's table: two texels per entry
        Texture scratch = Texture::create(sat ? satTableWidth(input.width) : input.width,
                                          input.height, GL_RGBA32F);
        Texture dst = Texture::create(input.width, input.height, GL_RGBA32F);
        src.upload(input);
        const ShadowEffect& fx = scene.shadow;
        if (is(a, Stage::Gaussian)) {
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
        const Image& filtered = result.images["moments_filtered"] = dst.read();
        clock.lap("filter passes (compile, dispatch) and read-back");
        if (sat && fx.satPerPixel)  // satKernelTexels on the same moments (sat_kernel_ladder.h)
            result.images[kSatKernelImage] = satKernelLadder(makeLibrary(a), scene, input);
        // Which of the stage's functions is the stub, each probed alone (a stub table makes a
        // correct lookup return 0, not -1): only when the output hints at one.
        bool hint = false;
        for (size_t i = 0, n = size_t(filtered.width) * filtered.height; i < n && !hint; ++i)
            hint = filtered.stubTexel(i) || (sat && !(filtered.pixels[i * 4] > 0.0f));
        if (auto k = result.images.find(kSatKernelImage); k != result.images.end())
            for (float w : k->second.pixels) hint = hint || w == -1.0f;
        std::vector<StageFunction> functions = {StageFunction::GaussianPass};
        if (sat) functions = {StageFunction::SatPass, StageFunction::SatBoxAverage};
        if (sat && fx.satPerPixel) functions.push_back(StageFunction::SatKernelTexels);
        const ShaderLibrary library = makeLibrary(a);
        if (hint)
            for (StageFunction f : stubFunctions(library, functions))
                result.stubNotes.push_back(
                    stubNoteText(library.displayPath(library.resolve(stageFunction(f).file)), f));
    } else if (is(a, Stage::Msm)) {
        // Lighting only, from the reference's filtered moments and each fragment's zf (files:
        // isolated with the goldens alone; no moments.glsl is compiled).
        result = renderFromMoments(renderer, scene, readAnyImage(a.input),
                                   relativeDepthBeside(scene, a.input));
        clock.lap("lighting (compile, passes) and read-back");
    } else if (!a.stage) {
        result = gradedReferenceImages(renderer, scene);
        clock.lap("the reference's images (compile, passes, read-back)");
    } else {
        PassPlan plan;
        if (is(a, Stage::Moments)) {
            // Only the shadow passes: nothing else compiles, so only moments.glsl can fail.
            scene.shadow.filter = FilterKind::None;
            plan = planPasses(scene);
            std::erase_if(plan.passes,
                          [](const PlannedPass& p) { return p.kind != PassKind::Shadow; });
        } else {
            // The reference's filtered map is the msm stage's input; in `final` the resolve is
            // what finds a stub satBoxAverage ("not implemented", docs/grading.md, "Speed").
            plan = planPasses(scene, {.resolveSat = true});
        }
        renderer.compilePrograms(scene, plan);
        clock.lap("shader compile (JIT)");
        result = renderer.render(scene, plan);
        clock.lap("passes and read-back");
        completeStubNotes(makeLibrary(a), plan, result);  // every stub the render runs, by name
        if (is(a, Stage::Moments))  // relativeDepth outside [near, far] too (depth_ladder.h)
            result.images[kDepthLadderImage] =
                depthLadderImage(probeMoments(makeLibrary(a), relativeDepthLadder()));
    }
    clock.lap("stage extras (ladders, probes, isolated render)");
    fs::create_directories(a.out);
    for (const auto& [name, image] : result.images) {
        if (isImage(name, ImageKind::Sat)) continue;  // the table itself is never compared
        if (a.stage && !a.stage->images.empty() && !stageImage(*a.stage, name)) continue;
        writeRaw(image, fs::path(a.out) / (name + ".raw"));
        out.images.push_back(name);
    }
    // The stage is the stub everywhere (the grader then skips its renders of the other scenes,
    // grade.cpp): a filter's whole output is -1; computeMoments gave -1 on every rung of the
    // depth ladder (the map's background keeps its clear value, so the map cannot tell).
    if (a.stage && a.stage->scoutedBy == a.stage->stage) {
        const std::string shown = is(a, Stage::Moments) ? kDepthLadderImage : toString(a.stage->images.front());
        if (auto it = result.images.find(shown); it != result.images.end())
            out.stubEverywhere = it->second.allStub();
    }
    out.scene = scene.name;
    for (const auto& n : result.stubNotes) out.stubNotes.push_back(stubNote(n));
    std::ofstream(fs::path(a.out) / kWorkerResultFile) << out.toJson().dump(2) << "\n";
    clock.lap("image files (.raw)");
}

int workerMain(const WorkerArgs& a) {
    try {
        runWorker(a);
        return Ok;
    } catch (...) {
        return reportError(std::current_exception(), std::cerr);
    }
}

}  // namespace sl::grader
