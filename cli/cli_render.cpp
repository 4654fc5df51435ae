// cli_render: the subcommands that render and measure.
//   render  renders one scene through a solution and writes its images and sidecar
//   bench   (cli_bench.cpp) times the filter passes against a copy pass
//   compare (cli_compare.cpp) the technique ladder side by side
//   info    prints the GL backend, renderer and Mesa version
#include "cli_commands.h"
#include "gl_context.h"
#include "huge_pages.h"
#include "image_io.h"
#include "pass_plan.h"
#include "paths.h"
#include "probe_check.h"
#include "render_output.h"
#include "renderer.h"
#include "scene.h"
#include "stub_survey.h"
#include "technique.h"

#include <cstdio>
#include <fstream>
#include <iostream>

namespace sl::cli {

void addCompareCommand(CLI::App& app, Context& ctx);  // compare (cli_compare.cpp)

void addBenchCommand(CLI::App& app, Context& ctx);  // bench (cli_bench.cpp)

namespace {

// "vsm:bleedReduction=0.3" -> "vsm_bleedReduction-0.3": one folder per spec.
std::string specFolder(std::string spec) {
    for (char& c : spec) c = c == ':' ? '_' : c == '=' ? '-' : c;
    return spec;
}

int runRender(const std::string& scenePath, const std::string& solution,
              const std::string& outDir, const std::string& backend, bool explain,
              const std::string& techniques, bool filteredMoments) {
    const Scene loaded = loadScene(scenePath);
    fs::path solutionDir = resolveSolution(solution);
    auto context = createContext(parseBackendKind(backend));
    const ShaderLibrary library = ShaderLibrary::forSolution(solutionDir, repoRoot());
    Renderer renderer(library);
    // `--technique T[,T2,...]`: one render per technique; several go to <out>/<name>/.
    std::vector<std::string> specs;
    for (size_t start = 0; !techniques.empty() && start <= techniques.size();) {
        size_t comma = techniques.find(',', start);
        if (comma == std::string::npos) comma = techniques.size();
        specs.push_back(techniques.substr(start, comma - start));
        start = comma + 1;
    }
    const std::string shaders = (repoRoot() / "shaders").string();
    if (specs.size() == 1 && specs[0] == "all") {
        specs.clear();
        for (const TechniqueRow& row : techniqueTable()) {
            if (techniqueInKit(row, shaders)) specs.push_back(row.name);
            else std::cout << "skipped " << row.name << " (not in the student kit: " << row.solvesStage << ")\n";
        }
    }
    if (specs.empty()) specs.push_back("");
    for (const std::string& spec : specs) {
        Scene scene = loaded;
        // Without --out, one folder per scene: a render never spills loose files into out/.
        fs::path out = outDir.empty() ? fs::path("out") / loaded.name : fs::path(outDir);
        if (!spec.empty()) {
            auto [technique, parameters] = parseTechniqueSpec(spec);
            const TechniqueRow& row = techniqueRow(technique);
            if (!techniqueInKit(row, shaders))
                throw std::invalid_argument("technique \"" + row.name + "\" is not in the student kit (" +
                                            row.solvesStage + "); its golden images are in "
                                            "scenes/goldens/<scene>/ladder/");
            overrideTechnique(scene.shadow, technique, parameters);
            if (specs.size() > 1) out /= specFolder(spec);
        }
        PassPlan plan = planPasses(scene, {.resolveSat = filteredMoments});
        RenderResult result = renderer.render(scene, plan);
        completeStubNotes(library, plan, result);  // one stub hides another from the output
        writeRenderOutputs(scene, plan, result, {solution, context->info()}, out);
        if (explain) std::cout << explainPlan(scene, plan, &result.passMillis);
        for (const auto& note : result.stubNotes) std::cout << "note: " << note << "\n";
        // The scene's probes (docs/scenes.md): the reference must meet them (a wrong probe is a
        // scene error, after the images are written); any other solution just hears about it.
        if (spec.empty() && !scene.probes.empty() && !result.stubNotes.empty() && solution != "reference")
            std::cout << "probes: not checked while a stage is a stub (the notes above)\n";
        else if (spec.empty() && !scene.probes.empty()) {
            const auto failures = probeFailures(scene, [&](const std::string& name) -> const Image* {
                auto it = result.images.find(name);
                return it == result.images.end() ? nullptr : &it->second;
            }, solution);
            if (!failures.empty() && solution == "reference") {
                std::string all;
                for (const auto& f : failures) all += "\n" + f;
                throw SceneError("the reference render (written to " + out.string() +
                                 ") does not match " + std::to_string(failures.size()) +
                                 " probe(s):" + all);
            }
            for (const auto& f : failures) std::cout << "note: probe: " << f << "\n";
            if (failures.empty())
                std::cout << "probes: all " << scene.probes.size() << " hold\n";
        }
        std::string names;
        for (const auto& [name, image] : result.images) names += (names.empty() ? "" : ",") + name;
        std::cout << "wrote " << out.string() << "/{" << names << "}.exr, their .png previews "
                  << "and render.json (" << toString(scene.shadow.technique) << ", "
                  << context->info().backend << ", " << context->info().renderer << ")\n";
    }
    return Ok;
}

}  // namespace

void addRenderCommands(CLI::App& app, Context& ctx) {
    auto* render = app.add_subcommand("render", "render a scene through a solution");
    struct RenderArgs {
        std::string scene, solution = defaultSolution(), out;
        bool explain = false, filteredMoments = false;
        std::string technique;
    };
    auto args = std::make_shared<RenderArgs>();
    render->add_option("--scene", args->scene, "scene JSON file")->required();
    render->add_option("--solution", args->solution,
                       "reference, student, or a folder of stage files");
    render->add_option("--out", args->out, "output folder (default: out/<scene name>)");
    render->add_flag("--explain", args->explain, "print the pass plan and the time of each pass");
    render->add_flag("--filtered-moments", args->filteredMoments,
                     "also write moments_filtered for a SAT filter (the solution's box average at "
                     "every texel: a pass of its own that no frame needs)");
    render->add_option("--technique", args->technique,
                       "override the scene's technique: T[,T2,...] or all; T may carry parameters, "
                       "T:name=value[:name=value] (docs/techniques.md)");
    render->callback([args, &ctx] {
        ctx.exitCode = runRender(args->scene, args->solution, args->out, ctx.backend, args->explain,
                                 args->technique, args->filteredMoments);
    });

    addBenchCommand(app, ctx);  // cli_bench.cpp

    addCompareCommand(app, ctx);  // cli_compare.cpp

    auto* info = app.add_subcommand("info", "print the GL backend and renderer");
    info->callback([&ctx] {
        auto context = createContext(parseBackendKind(ctx.backend));
        const auto& i = context->info();
        std::cout << "backend:  " << i.backend << "\nwhy:      " << i.choice << "\nrenderer: " << i.renderer
                  << "\nversion:  " << i.version << "\nmesa:     " << i.mesaVersion
                  << "\nhuge pages: " << hugePagesState() << "\n";
        ctx.exitCode = Ok;
    });
}

}  // namespace sl::cli
