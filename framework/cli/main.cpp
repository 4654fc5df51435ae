// shadowlab: the command line. The subcommands live in cli_*.cpp and grader/cli_*.cpp; this
// file parses and turns every error into a message and an exit code (cli_commands.h).
#include "cli_commands.h"
#include "gl_context.h"
#include "scene.h"
#include "shader_source.h"

#include <iostream>

int main(int argc, char** argv) {
    CLI::App app{"Shadowlab: filtered moment shadow maps on Mesa's software rasterizer"};
    app.require_subcommand(1);
    sl::cli::Context ctx;
    app.add_option("--backend", ctx.backend, "GL backend: auto (OSMesa, else EGL), osmesa or egl")
        ->check(CLI::IsMember({"auto", "osmesa", "egl"}));
    sl::cli::addRenderCommands(app, ctx);
    sl::cli::addViewCommand(app, ctx);
    sl::cli::addProbeCommand(app, ctx);
    sl::cli::addStudyCommands(app, ctx);
    sl::cli::addProjectCommand(app, ctx);
    sl::cli::addGraderCommands(app, ctx);
    try {
        app.parse(argc, argv);
        return ctx.exitCode;
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const sl::SceneError& e) {
        std::cerr << "scene error: " << e.what() << "\n";
        return sl::cli::BadInput;
    } catch (const sl::ShaderError& e) {
        std::cerr << "shader error:\n" << e.what() << "\n";
        return sl::cli::ShaderFailed;
    } catch (const sl::BackendError& e) {
        std::cerr << "no OpenGL: " << e.what() << "\n";
        return sl::cli::NoBackend;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return sl::cli::Failed;
    }
}
