// shadowlab: the command line. The subcommands live in cli_*.cpp (the grader's in cli_grade.cpp); this
// file parses and turns every error into a message and an exit code (cli_commands.h). Global
// options live here too: --backend is accepted before the subcommand and on every subcommand
// that renders; the kit's root (paths.h) is reported by info and grade.
#include "cli_commands.h"
#include "codec_child.h"
#include "gl_context.h"
#include "huge_pages.h"
#include "paths.h"
#include "scene.h"
#include "shader_source.h"

#include <cstdlib>
#include <unistd.h>
#include <iostream>
#include <set>

namespace sl::cli {
void addReportCommand(CLI::App& app, Context& ctx);  // report (cli_report.cpp)
}

namespace {

// Subcommands that render nothing (no --backend there).
const std::set<std::string> kNoGl = {"package", "project"};
// Subcommands that say which kit root they use (stdout), as instructors need to know.
const std::set<std::string> kSayRoot = {"info", "grade", "golden", "package"};

void addBackendOption(CLI::App& app, std::string& backend) {
    app.add_option("--backend", backend, "GL backend: auto (OSMesa, else EGL), osmesa or egl")
        ->check(CLI::IsMember({"auto", "osmesa", "egl"}));
}

}  // namespace

int main(int argc, char** argv) {
    // The image codec's child (codec_child.h): not a user command, no parsing, no re-exec.
    // Its answers own stdout; whatever a library prints goes to stderr.
    if (argc == 2 && std::string(argv[1]) == "codec-server") {
        const int answers = ::dup(1);
        ::dup2(2, 1);
        return sl::serveCodec(0, answers, sl::moduleCodec());
    }
    sl::cli::useHugePages(argc, argv);  // may re-execute this program once (huge_pages.h)
    CLI::App app{"Shadowlab: filtered moment shadow maps on Mesa's software rasterizer"};
    app.require_subcommand(1);
    sl::cli::Context ctx;
    addBackendOption(app, ctx.backend);
    sl::cli::addRenderCommands(app, ctx);
    sl::cli::addReportCommand(app, ctx);
    sl::cli::addViewCommand(app, ctx);
    sl::cli::addProbeCommand(app, ctx);
    sl::cli::addStudyCommands(app, ctx);
    sl::cli::addProjectCommand(app, ctx);
    sl::cli::addGraderCommands(app, ctx);
    // `shadowlab render --backend egl ...` as well as `shadowlab --backend egl render ...`.
    for (CLI::App* sub : app.get_subcommands({}))
        if (!kNoGl.count(sub->get_name()) && !sub->get_option_no_throw("--backend"))
            addBackendOption(*sub, ctx.backend);
    // Before the subcommand runs: fix the root for child processes (grade workers), and say it.
    app.parse_complete_callback([&app] {
        const sl::fs::path root = sl::repoRoot();
        const std::string origin = sl::repoRootOrigin(), warning = sl::repoRootWarning();
        ::setenv("SHADOWLAB_ROOT", root.c_str(), 1);
        for (CLI::App* sub : app.get_subcommands()) {
            if (sub->get_name() == "grade-worker" || sub->get_name() == "grade-submission") return;
            if (kSayRoot.count(sub->get_name()))
                std::cout << "kit root: " << root.string() << " (from " << origin << ")\n";
        }
        if (!warning.empty()) std::cerr << warning << "\n";
    });
    try {
        app.parse(argc, argv);
        return ctx.exitCode;
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (...) {
        return sl::reportError(std::current_exception(), std::cerr);
    }
}
