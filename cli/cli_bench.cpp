// cli_bench: `shadowlab bench`: times a solution's filter passes against a copy pass (the
// verdict's yardstick, docs/performance.md) and a tiled copy (the column "tiled": what moving the
// texels costs on llvmpipe), and its SAT lookup's lighting pass against a bilinear fetch
// (filter_benchmark.h, docs/performance.md).
//   --json          print the figures as JSON instead of the table
//   --json FILE     also write them to FILE
#include "cli_commands.h"
#include "filter_benchmark.h"
#include "gl_context.h"
#include "huge_pages.h"
#include "paths.h"
#include "renderer.h"

#include <fstream>
#include <iostream>

namespace sl::cli {
namespace {

struct BenchArgs {
    int size = 1024, repeats = 21;
    std::string solution = defaultSolution(), json, lightingScene = "scenes/wide_blur.json";
    bool jsonGiven = false;
};

int runBench(const BenchArgs& a, const std::string& backend) {
    auto context = createContext(parseBackendKind(backend));
    Renderer renderer(ShaderLibrary::forSolution(resolveSolution(a.solution), repoRoot()));
    BenchOptions options{a.size, a.repeats, ""};
    if (a.lightingScene != "none") {
        fs::path scene = a.lightingScene;
        if (scene.is_relative() && !fs::exists(scene)) scene = repoRoot() / scene;
        options.lightingScene = scene.string();
    }
    BenchReport report = runFilterBenchmark(renderer, options);
    if (a.jsonGiven && a.json.empty()) {
        std::cout << benchReportJson(report) << "\n";
        return Ok;
    }
    std::cout << "filter benchmark: " << a.solution << " on " << context->info().renderer << ", "
              << context->info().version << "\nhuge pages: " << hugePagesState() << "\n"
              << formatBenchReport(report);
    if (!a.json.empty()) std::ofstream(a.json) << benchReportJson(report) << "\n";
    return Ok;
}

}  // namespace

void addBenchCommand(CLI::App& app, Context& ctx) {
    auto* bench = app.add_subcommand(
        "bench", "time the filter passes against a copy pass and a tiled copy, with spreads and goals");
    auto b = std::make_shared<BenchArgs>();
    bench->add_option("--size", b->size, "texture size (square, RGBA32F)")->check(CLI::Range(16, 4096));
    bench->add_option("--repeats", b->repeats, "measured repeats per pass")->check(CLI::Range(3, 1000));
    bench->add_option("--solution", b->solution, "whose filters to time (reference, student, a folder)");
    auto* json = bench->add_option("--json", b->json,
                                   "print the figures as JSON; with FILE, also write them there")
                     ->expected(0, 1);
    bench->add_option("--lighting-scene", b->lightingScene,
                      "SAT scene whose lighting pass is timed against a bilinear fetch, or none");
    bench->callback([b, json, &ctx] {
        b->jsonGiven = json->count() > 0;
        ctx.exitCode = runBench(*b, ctx.backend);
    });
}

}  // namespace sl::cli
