// cli_render: the subcommands that render and measure.
//   render  renders one scene through a solution and writes its images and sidecar
//   bench   (cli_bench.cpp) times the filter passes against a copy pass
//   info    prints the GL backend, renderer and Mesa version
#include "cli_commands.h"
#include "gl_context.h"
#include "image_io.h"
#include "pass_plan.h"
#include "paths.h"
#include "render_output.h"
#include "renderer.h"
#include "scene.h"

#include <cstdio>
#include <fstream>
#include <iostream>

namespace sl::cli {

void addBenchCommand(CLI::App& app, Context& ctx);  // bench (cli_bench.cpp)

namespace {

int runRender(const std::string& scenePath, const std::string& solution,
              const std::string& outDir, const std::string& backend, bool explain) {
    Scene scene = loadScene(scenePath);
    fs::path solutionDir = resolveSolution(solution);
    auto context = createContext(parseBackendKind(backend));
    PassPlan plan = planPasses(scene);
    Renderer renderer(ShaderLibrary::forSolution(solutionDir, repoRoot()));
    RenderResult result = renderer.render(scene, plan);
    writeRenderOutputs(scene, plan, result, {solution, context->info()}, outDir);
    if (explain) std::cout << explainPlan(scene, plan, &result.passMillis);
    for (const auto& note : result.stubNotes) std::cout << "note: " << note << "\n";
    std::cout << "wrote " << outDir << "/{final,shadow,moments_raw,moments_filtered}.{exr,png} "
              << "and render.json (" << context->info().backend << ", "
              << context->info().renderer << ")\n";
    return Ok;
}

}  // namespace

void addRenderCommands(CLI::App& app, Context& ctx) {
    auto* render = app.add_subcommand("render", "render a scene through a solution");
    struct RenderArgs {
        std::string scene, solution = "reference", out = "out";
        bool explain = false;
    };
    auto args = std::make_shared<RenderArgs>();
    render->add_option("--scene", args->scene, "scene JSON file")->required();
    render->add_option("--solution", args->solution,
                       "reference, student, or a folder of stage files");
    render->add_option("--out", args->out, "output folder");
    render->add_flag("--explain", args->explain, "print the pass plan and the time of each pass");
    render->callback([args, &ctx] {
        ctx.exitCode = runRender(args->scene, args->solution, args->out, ctx.backend, args->explain);
    });

    addBenchCommand(app, ctx);  // cli_bench.cpp

    auto* info = app.add_subcommand("info", "print the GL backend and renderer");
    info->callback([&ctx] {
        auto context = createContext(parseBackendKind(ctx.backend));
        const auto& i = context->info();
        std::cout << "backend:  " << i.backend << "\nrenderer: " << i.renderer
                  << "\nversion:  " << i.version << "\nmesa:     " << i.mesaVersion << "\n";
        ctx.exitCode = Ok;
    });
}

}  // namespace sl::cli
