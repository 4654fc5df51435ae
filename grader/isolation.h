// isolation.h: runs grader workers as child processes under a time and a memory limit.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace sl::grader {

struct ChildSpec {
    std::vector<std::string> args;   // argv[1..] for this executable (the worker subcommand)
    std::filesystem::path logPath;   // the child's stdout + stderr
};

struct ChildResult {
    enum Kind { Exited, Signalled, TimedOut, StartFailed } kind = StartFailed;
    int exitCode = -1;
    int signal = 0;
    double seconds = 0.0;
    std::string log;  // the child's stdout + stderr (first 64 KiB)
};

struct Limits {
    double timeoutSeconds = 20.0;
    long memoryMb = 4096;
};

// The path of the running executable (/proc/self/exe): workers are this binary.
std::string selfExecutable();

// Runs every spec, at most `parallel` at a time; `done(i, result)` is called as each ends.
std::vector<ChildResult> runChildren(const std::vector<ChildSpec>& specs, const Limits& limits,
                                     int parallel,
                                     const std::function<void(size_t, const ChildResult&)>& done = {});

std::string signalName(int signal);  // "SIGSEGV (Segmentation fault)"

}  // namespace sl::grader
