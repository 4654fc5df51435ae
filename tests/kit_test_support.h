// kit_test_support: what the kit's own tests share — the command lines a Markdown file shows
// (so that every new line in README/handout is tested without editing a test), running one
// with a time limit in a folder, and the build folder this test binary belongs to.
#pragma once

#include "gl_test_support.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <future>
#include <memory>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace sl::test {

// build/ (or build-<name>/): the folder holding this test binary's tests/ folder.
inline fs::path buildDir() { return fs::read_symlink("/proc/self/exe").parent_path().parent_path(); }

// The command lines a Markdown file shows: lines of ```sh code blocks and inline code spans
// that start with `./kit ` or `build/shadowlab ` (a span's line breaks become spaces), with a
// trailing `# comment` removed, in the order of the file.
inline std::vector<std::string> documentedCommands(const std::string& markdown) {
    std::vector<std::string> out;
    auto keep = [&](std::string line) {
        line = std::regex_replace(line, std::regex(R"(\s+#\s.*$)"), "");
        line = std::regex_replace(line, std::regex(R"(\s+)"), " ");
        line = std::regex_replace(line, std::regex(R"(^ | $)"), "");
        if (line.rfind("./kit", 0) == 0 || line.rfind("build/shadowlab ", 0) == 0 ||
            line.rfind("xvfb-run -a build/shadowlab ", 0) == 0)
            out.push_back(line);
    };
    std::istringstream in(markdown);
    std::string line, prose;
    bool block = false;
    auto flushProse = [&] {
        static const std::regex span("`([^`]+)`");
        for (std::sregex_iterator it(prose.begin(), prose.end(), span), end; it != end; ++it)
            keep((*it)[1].str());
        prose.clear();
    };
    while (std::getline(in, line)) {
        if (line.rfind("```", 0) == 0) {
            if (!block) flushProse();
            block = !block;
            continue;
        }
        if (block) keep(line);
        else prose += line + "\n";
    }
    flushProse();
    // A command shown twice (block and prose) runs once.
    std::vector<std::string> unique;
    for (const auto& c : out)
        if (std::find(unique.begin(), unique.end(), c) == unique.end()) unique.push_back(c);
    return unique;
}

// Runs `command` with bash in `dir`, killed after `seconds` (exit code 124 then).
inline CommandResult runIn(const fs::path& dir, const std::string& command, int seconds,
                           const std::string& env = "") {
    std::string quoted = "'";
    for (char c : command) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    quoted += "'";
    return runCommand("cd '" + dir.string() + "' && " + env + " timeout -k 5 " +
                      std::to_string(seconds) + " bash -c " + quoted + " </dev/null");
}

// The student kit as a student gets it: `shadowlab package --kind student` into
// dir/shadowlab-student.tar.gz, unpacked in dir (its one top folder: dir/shadowlab).
struct UnpackedKit {
    fs::path tarball, root;            // root: dir/shadowlab
    std::vector<std::string> entries;  // the tarball's entries, as `tar tzf` lists them
    std::string error;                 // "" when packing and unpacking worked, else why not
};
inline UnpackedKit unpackStudentKit(const fs::path& dir) {
    UnpackedKit k{dir / "shadowlab-student.tar.gz", dir / "shadowlab", {}, ""};
    const auto pack = runCommand(shadowlabBinary() + " package --kind student --out '" + k.tarball.string() + "'");
    if (pack.exitCode != 0) {
        k.error = "package: exit " + std::to_string(pack.exitCode) + "\n" + pack.output;
        return k;
    }
    std::istringstream list(runCommand("tar tzf '" + k.tarball.string() + "'").output);
    for (std::string l; std::getline(list, l);) k.entries.push_back(l);
    const auto untar = runCommand("tar xzf '" + k.tarball.string() + "' -C '" + dir.string() + "'");
    if (untar.exitCode != 0) k.error = "tar xzf: " + untar.output;
    return k;
}

// Builds the kit's `shadowlab` program in kit/build as `./kit demo` does (ccache makes the
// compiles hits when this build used it).
inline CommandResult buildKitProgram(const fs::path& kit) {
    return runIn(kit, "cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null && "
                      "cmake --build build --target shadowlab", 900);
}

// How the kit's tests run a documented command line: as written, except
//  - `./kit test` where `skipKitTest` (it is the command running this test),
//  - `./kit deps --check` (it traces a whole build, minutes; .ci/run runs it after the suite),
//  - `./kit study` (the full study, ~15 minutes; tests/test_study.cpp runs a tiny sweep),
//  - benchmarks get `--size 64 --repeats 3` (a full-size benchmark is a minute of CPU), and
//    `bench --exact` also `--lighting-scene none` (its lighting rows are minutes under valgrind),
//  - `view` runs under xvfb-run (a virtual display; a line may say `xvfb-run -a` itself), and a
//    time limit closes its window; with --screenshot it ends by itself and must succeed.
// Returns "" when it passed, else what went wrong (the command, its exit code, its output).
inline std::string runDocumented(const fs::path& dir, std::string command, bool skipKitTest,
                                 const std::string& env, std::string* skipped = nullptr) {
    if (command == "./kit test" && skipKitTest) {
        if (skipped) *skipped += command + ": skipped (it is the command running this test)\n";
        return "";
    }
    if (command == "./kit deps --check") {
        if (skipped) *skipped += command + ": skipped (.ci/run runs it after the test suite)\n";
        return "";
    }
    if (command == "./kit study") {
        if (skipped) *skipped += command + ": skipped (about 15 minutes; Study.* run a tiny sweep)\n";
        return "";
    }
    const bool view = command.find("shadowlab view") != std::string::npos;
    // A window that stays open until the time limit closes it (a screenshot ends by itself).
    const bool window = view && command.find("--screenshot") == std::string::npos;
    if (command.find(" bench") != std::string::npos && command.find("--size") == std::string::npos)
        command += " --size 64 --repeats 3";
    // Under valgrind the lighting rows are minutes; KitBenchLabel runs --exact at the goals' size.
    if (command.find(" bench --exact") != std::string::npos && command.find("--lighting-scene") == std::string::npos)
        command += " --lighting-scene none";
    if (view) {
        if (runCommand("command -v xvfb-run").exitCode != 0) {
            if (skipped) *skipped += command + ": skipped (no xvfb-run; ./kit installs xvfb)\n";
            return "";
        }
        if (command.rfind("xvfb-run ", 0) != 0) command = "xvfb-run -a " + command;
    }
    const auto t0 = std::chrono::steady_clock::now();
    CommandResult r = runIn(dir, command, window ? 8 : 900, env);
    std::printf("  %6.1f s  %s\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
                command.c_str());
    // A window that is still open when the time limit ends it ran without an error.
    const bool ok = r.exitCode == 0 || (window && r.exitCode == 124);
    if (ok) return "";
    return command + "\n  exit " + std::to_string(r.exitCode) + "\n" + r.output + "\n";
}

// Every command of `commands` through runDocumented, in order, in `dir`; returns the failures.
// A window (`shadowlab view`) writes nothing and only waits out its time limit, most of it
// idle: it runs alongside the commands after it (8 s less per call) and is joined at the end.
inline std::string runDocumentedCommands(const fs::path& dir, const std::vector<std::string>& commands,
                                         bool skipKitTest, const std::string& env,
                                         std::string* skipped = nullptr) {
    struct Window {
        std::future<std::string> failure;
        std::string skipped;
    };
    std::vector<std::unique_ptr<Window>> windows;
    std::string failures;
    for (const auto& c : commands) {
        if (c.find("shadowlab view") != std::string::npos) {
            auto w = std::make_unique<Window>();
            w->failure = std::async(std::launch::async, [=, s = &w->skipped] {
                return runDocumented(dir, c, skipKitTest, env, s);
            });
            windows.push_back(std::move(w));
        } else {
            failures += runDocumented(dir, c, skipKitTest, env, skipped);
        }
    }
    for (auto& w : windows) {
        failures += w->failure.get();
        if (skipped) *skipped += w->skipped;
    }
    return failures;
}

}  // namespace sl::test
