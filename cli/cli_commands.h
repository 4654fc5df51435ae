// cli_commands: how the shadowlab subcommands register themselves. Each file under cli/ adds its
// subcommands (the framework's and the grader's alike); main.cpp parses and maps errors to exit
// codes (exit_codes.h).
#pragma once

#include "exit_codes.h"

#include <CLI/CLI.hpp>

#include <string>

namespace sl::cli {

// Shared by all subcommands; a subcommand's callback sets exitCode.
struct Context {
    std::string backend = "auto";
    int exitCode = Ok;
};

void addRenderCommands(CLI::App& app, Context& ctx);  // render, info, bench, compare
void addViewCommand(CLI::App& app, Context& ctx);    // view (cli_view.cpp, GLFW window)
void addProbeCommand(CLI::App& app, Context& ctx);    // probe (cli_probe.cpp)
void addStudyCommands(CLI::App& app, Context& ctx);   // study, truth (cli_study.cpp)
void addProjectCommand(CLI::App& app, Context& ctx);  // project (cli_project.cpp)
void addGraderCommands(CLI::App& app, Context& ctx);  // grade, golden, package (cli_grade.cpp)

}  // namespace sl::cli
