// shadowlab: the command line. Subcommands:
//   render  renders one scene through a solution and writes its images and sidecar
//   bench   times the filter passes against a copy pass (docs/performance.md)
//   info    prints the GL backend, renderer and Mesa version
#include "filter_benchmark.h"
#include "gl_context.h"
#include "image_io.h"
#include "pass_plan.h"
#include "paths.h"
#include "render_output.h"
#include "renderer.h"
#include "scene.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <iostream>

namespace {

enum ExitCode { Ok = 0, BadInput = 2, ShaderFailed = 3, NoBackend = 4, Failed = 1 };

int runRender(const std::string& scenePath, const std::string& solution,
              const std::string& outDir, const std::string& backend, bool explain) {
    sl::Scene scene = sl::loadScene(scenePath);
    sl::fs::path solutionDir = sl::resolveSolution(solution);
    auto context = sl::createContext(sl::parseBackendKind(backend));
    sl::PassPlan plan = sl::planPasses(scene);
    sl::Renderer renderer(sl::ShaderLibrary::forSolution(solutionDir, sl::repoRoot()));
    sl::RenderResult result = renderer.render(scene, plan);
    sl::writeRenderOutputs(scene, plan, result, {solution, context->info()}, outDir);
    if (explain) std::cout << sl::explainPlan(scene, plan, &result.passMillis);
    for (const auto& note : result.stubNotes) std::cout << "note: " << note << "\n";
    std::cout << "wrote " << outDir << "/{final,shadow,moments_raw,moments_filtered}.{exr,png} "
              << "and render.json (" << context->info().backend << ", "
              << context->info().renderer << ")\n";
    return Ok;
}

int runBench(int size, int repeats, const std::string& solution, const std::string& backend,
             const std::string& jsonPath) {
    auto context = sl::createContext(sl::parseBackendKind(backend));
    sl::Renderer renderer(
        sl::ShaderLibrary::forSolution(sl::resolveSolution(solution), sl::repoRoot()));
    sl::BenchReport report = sl::runFilterBenchmark(renderer, size, repeats);
    std::cout << "filter benchmark: " << solution << " on " << context->info().renderer << ", "
              << context->info().version << "\n"
              << sl::formatBenchReport(report);
    if (!jsonPath.empty()) std::ofstream(jsonPath) << sl::benchReportJson(report) << "\n";
    return Ok;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Shadowlab: filtered moment shadow maps on Mesa's software rasterizer"};
    app.require_subcommand(1);
    std::string backend = "auto";
    app.add_option("--backend", backend, "GL backend: auto (OSMesa, else EGL), osmesa or egl")
        ->check(CLI::IsMember({"auto", "osmesa", "egl"}));

    auto* render = app.add_subcommand("render", "render a scene through a solution");
    std::string scenePath, solution = "reference", outDir = "out";
    bool explain = false;
    render->add_option("--scene", scenePath, "scene JSON file")->required();
    render->add_option("--solution", solution, "reference, student, or a folder of stage files");
    render->add_option("--out", outDir, "output folder");
    render->add_flag("--explain", explain, "print the pass plan and the time of each pass");

    auto* bench = app.add_subcommand("bench", "time the filter passes against a copy pass");
    int size = 1024, repeats = 21;
    std::string jsonPath, benchSolution = "reference";
    bench->add_option("--size", size, "texture size (square, RGBA32F)")->check(CLI::Range(16, 4096));
    bench->add_option("--repeats", repeats, "measured repeats per pass")->check(CLI::Range(3, 1000));
    bench->add_option("--solution", benchSolution, "whose filters to time");
    bench->add_option("--json", jsonPath, "also write the figures as JSON");

    auto* info = app.add_subcommand("info", "print the GL backend and renderer");

    CLI11_PARSE(app, argc, argv);
    try {
        if (*render) return runRender(scenePath, solution, outDir, backend, explain);
        if (*bench) return runBench(size, repeats, benchSolution, backend, jsonPath);
        if (*info) {
            auto context = sl::createContext(sl::parseBackendKind(backend));
            const auto& i = context->info();
            std::cout << "backend:  " << i.backend << "\nrenderer: " << i.renderer
                      << "\nversion:  " << i.version << "\nmesa:     " << i.mesaVersion << "\n";
            return Ok;
        }
    } catch (const sl::SceneError& e) {
        std::cerr << "scene error: " << e.what() << "\n";
        return BadInput;
    } catch (const sl::ShaderError& e) {
        std::cerr << "shader error:\n" << e.what() << "\n";
        return ShaderFailed;
    } catch (const sl::BackendError& e) {
        std::cerr << "no OpenGL: " << e.what() << "\n";
        return NoBackend;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return Failed;
    }
    return Failed;
}
