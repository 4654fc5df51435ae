// cli_compare: `shadowlab compare` renders one scene with several techniques (the technique
// ladder side by side) and writes one image folder per technique, a contact sheet PNG (the
// final images in a grid, each labelled with its technique and its total pass time) and the
// same sheet as an HTML page with every pass's format, memory and time.
#include "cli_commands.h"
#include "gl_context.h"
#include "html_escape.h"
#include "image_io.h"
#include "pass_plan.h"
#include "paths.h"
#include "render_output.h"
#include "renderer.h"
#include "scene.h"
#include "scene_size.h"
#include "technique.h"

#include <cstdio>
#include <fstream>
#include <iostream>

namespace sl::cli {
namespace {

struct SheetEntry {
    std::string name, summary;
    double totalMs = 0.0;
    std::string passRows;  // HTML rows
    bool standIn = false;  // the golden reference image, not rendered here
};

// A row whose own files solve a stage is not in the student kit (TechniqueRow::solvesStage):
// there the sheet shows the image `shadowlab golden` made of it at the demo's sheet width.
fs::path standInImage(const TechniqueRow& row, const std::string& scenePath) {
    return repoRoot() / "scenes" / "goldens" / fs::path(scenePath).stem() / "ladder" /
           (row.name + ".png");
}

// The contact sheet: final images in a grid of `columns`, each labelled with its technique and
// total pass time (image_codec.h; the HTML sheet always names every image).
void writeSheetPng(const fs::path& outDir, const std::vector<SheetEntry>& entries, int columns) {
    std::vector<std::string> images, labels;
    for (const auto& e : entries) {
        images.push_back((outDir / e.name / "final.png").string());
        char label[128];
        if (e.standIn) std::snprintf(label, sizeof label, "%s (golden)", e.name.c_str());
        else std::snprintf(label, sizeof label, "%s  %.0f ms", e.name.c_str(), e.totalMs);
        labels.push_back(label);
    }
    imageCodec().contactSheet((outDir / "sheet.png").string(), images, labels, columns);
}

void writeSheetHtml(const fs::path& outDir, const Scene& scene,
                    const std::vector<SheetEntry>& entries, const ContextInfo& info) {
    std::ofstream html(outDir / "sheet.html");
    html << "<!doctype html><meta charset=\"utf-8\"><title>" << htmlEscape(scene.name)
         << ": technique ladder</title>\n<style>body{font-family:sans-serif;background:#1a1a1e;"
            "color:#ddd} .grid{display:flex;flex-wrap:wrap;gap:12px} figure{margin:0;width:"
            "min(100%,420px)} img{width:100%} table{font-size:12px;border-collapse:collapse}"
            " td{padding:1px 6px}</style>\n<h1>"
         << htmlEscape(scene.name) << ": the technique ladder</h1>\n<p>"
         << htmlEscape(scene.description) << "</p>\n<p>" << htmlEscape(info.renderer) << ", "
         << htmlEscape(info.version) << ". <a href=\"sheet.png\">contact sheet PNG</a></p>\n"
         << "<div class=\"grid\">\n";
    for (const auto& e : entries) {
        html << "<figure><img src=\"" << e.name << "/final.png\" alt=\"" << e.name
             << "\"><figcaption><b>" << e.name << "</b> — " << htmlEscape(e.summary);
        if (e.standIn) html << "</figcaption></figure>\n";
        else html << " (total " << std::fixed << e.totalMs << " ms)<table>" << e.passRows
                  << "</table></figcaption></figure>\n";
    }
    html << "</div>\n";
}

int runCompare(const std::string& scenePath, const std::string& techniques,
               const std::string& solution, const std::string& outDir, int columns, int size,
               bool sheetOnly, const std::string& backend) {
    Scene loaded = loadScene(scenePath);
    if (size > 0) scaleScene(loaded, size);  // a small sheet: the map and filters scale too
    std::vector<std::string> specs;
    if (techniques == "all") {
        specs = techniqueNames();
    } else {
        for (size_t start = 0; start <= techniques.size();) {
            size_t comma = techniques.find(',', start);
            if (comma == std::string::npos) comma = techniques.size();
            specs.push_back(techniques.substr(start, comma - start));
            start = comma + 1;
        }
    }
    auto context = createContext(parseBackendKind(backend));
    Renderer renderer(ShaderLibrary::forSolution(resolveSolution(solution), repoRoot()));
    std::vector<SheetEntry> entries;
    for (const std::string& spec : specs) {
        Scene scene = loaded;
        auto [technique, parameters] = parseTechniqueSpec(spec);
        const TechniqueRow& row = techniqueRow(technique);
        if (!techniqueInKit(row, (repoRoot() / "shaders").string())) {
            const std::string why = "not in the student kit: " + row.solvesStage;
            const fs::path standIn = standInImage(row, scenePath);
            if (!fs::exists(standIn)) {
                std::cout << "skipped " << row.name << " (" << why << "; no reference image for "
                          << "this scene)\n";
                continue;
            }
            fs::create_directories(fs::path(outDir) / row.name);
            fs::copy_file(standIn, fs::path(outDir) / row.name / "final.png",
                          fs::copy_options::overwrite_existing);
            std::cout << row.name << ": the reference image (" << why << ")\n";
            entries.push_back({row.name, row.summary + "; reference image, " + why, 0.0, "", true});
            continue;
        }
        overrideTechnique(scene.shadow, technique, parameters);
        PassPlan plan = planPasses(scene);
        RenderResult result = renderer.render(scene, plan);
        std::string folder = spec;  // "vsm:bleedReduction=0.3" -> "vsm_bleedReduction-0.3"
        for (char& c : folder) c = c == ':' ? '_' : c == '=' ? '-' : c;
        SheetEntry e{folder, row.summary};
        if (sheetOnly) {  // the one image the sheet shows (the rest: 2.5-3.3 -> 1.0-1.4 s a 256-px sheet)
            fs::create_directories(fs::path(outDir) / e.name);
            writePngPreview(result.images.at("final"), fs::path(outDir) / e.name / "final.png", true);
        } else {
            writeRenderOutputs(scene, plan, result, {solution, context->info()}, fs::path(outDir) / e.name);
        }
        for (size_t i = 0; i < plan.passes.size(); ++i) {
            const PlannedPass& p = plan.passes[i];
            const PlannedTexture* t = nullptr;
            for (const auto& c : plan.textures)
                if (c.role == p.writes && (p.light >= 0 ? c.light == p.light : c.camera == p.camera))
                    t = &c;
            char row[512];
            std::snprintf(row, sizeof row,
                          "<tr><td>%s</td><td>%s</td><td>%.2f MiB</td><td>%.1f ms</td></tr>",
                          toString(p.kind), t ? t->format.c_str() : "", t ? t->bytes / 1048576.0 : 0.0,
                          result.passMillis.at(i));
            e.passRows += row;
            e.totalMs += result.passMillis.at(i);
        }
        std::cout << explainPlan(scene, plan, &result.passMillis);
        entries.push_back(std::move(e));
    }
    writeSheetPng(outDir, entries, std::max(1, std::min(columns, int(entries.size()))));
    writeSheetHtml(outDir, loaded, entries, context->info());
    std::cout << "wrote " << outDir << (sheetOnly ? "/<technique>/final.png" : "/<technique>/")
              << ", sheet.png and sheet.html (" << entries.size() << " techniques)\n";
    return Ok;
}

}  // namespace

void addCompareCommand(CLI::App& app, Context& ctx) {
    auto* compare = app.add_subcommand("compare", "render a scene with several techniques, side by side");
    struct Args {
        std::string scene, techniques = "all", solution = defaultSolution(), out = "out/compare";
        int columns = 4, size = 0;
        bool sheetOnly = false;
    };
    auto a = std::make_shared<Args>();
    compare->add_option("--scene", a->scene, "scene JSON file")->required();
    compare->add_option("--techniques", a->techniques,
                        "all, or T[,T2,...] (T may carry parameters: vsm:bleedReduction=0.3)");
    compare->add_option("--solution", a->solution, "whose stages the msm4 row runs");
    compare->add_option("--out", a->out, "output folder");
    compare->add_option("--columns", a->columns, "images per row of the sheet")->check(CLI::Range(1, 16));
    compare->add_option("--size", a->size,
                        "image width in pixels (shadow map and filter widths scale with it); "
                        "default: the scene's")->check(CLI::Range(32, 4096));
    compare->add_flag("--sheet-only", a->sheetOnly,
                      "write the sheet and each technique's final.png only (no EXR, no other images)");
    compare->callback([a, &ctx] {
        ctx.exitCode = runCompare(a->scene, a->techniques, a->solution, a->out, a->columns, a->size,
                                  a->sheetOnly, ctx.backend);
    });
}

}  // namespace sl::cli
