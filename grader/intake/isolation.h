// isolation.h: runs grader workers as child processes under a time and a memory limit.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace sl::grader {

struct ChildSpec {
    std::vector<std::string> args;   // argv[1..] for this executable (the worker subcommand)
    std::filesystem::path logPath;   // the child's stdout + stderr
    double timeoutSeconds = 0.0;     // this child's limit; 0: Limits::timeoutSeconds
    std::string limitNote;           // how the limit was chosen, for the message
    // Children of one group (a stage): once one times out, the group's children not started
    // yet are not run; they get the same TimedOut result (skipped = true). "" : no group.
    std::string group;
    // Other groups whose code this child runs too (a final render runs the moments, filter and
    // msm stages' files): once one of them has timed out, this child is not run either.
    std::vector<std::string> alsoRuns;
    // (text, replacement) pairs applied to the log: the grader's own paths never reach a
    // student's message ("/work/kit/shaders/x" -> "shaders/x").
    std::vector<std::pair<std::string, std::string>> scrub;
    // Extra environment (name, value), set after the shader-cache defaults below.
    std::vector<std::pair<std::string, std::string>> env;
    // The child's work in this process, returning its exit code: run after fork without exec
    // while the grader has started no thread (an exec'd child loads the driver again). With
    // threads of its own (a GL context, an image library's pool) fork is unsafe: then `args`
    // are exec'd as before. Empty: always exec.
    std::function<int()> run;
    // Asked when this child's turn to start comes: true leaves it unstarted (notRun), e.g.
    // when another render already showed its stage to be the stub. Empty: always start.
    std::function<bool()> skipIf;
};

struct ChildResult {
    enum Kind { Exited, Signalled, TimedOut, StartFailed } kind = StartFailed;
    int exitCode = -1;
    int signal = 0;
    double seconds = 0.0;
    double cpuSeconds = 0.0;    // user + sys, its reaped descendants included (wait4)
    double limitSeconds = 0.0;  // the time limit it ran under
    std::string limitNote;      // ChildSpec::limitNote
    bool skipped = false;       // not run: its group timed out before (kind TimedOut)
    std::string skippedAfter;   // skipped because this group of alsoRuns timed out ("": its own)
    bool notRun = false;        // not started: its skipIf said so (kind StartFailed)
    std::string log;  // the child's stdout + stderr (first 64 KiB)
};

struct Limits {
    double timeoutSeconds = 20.0;
    long memoryMb = 4096;
    // Forked children of this call may run one after another in the same process, a runner
    // (at most `parallel` at a time): its libraries, driver screen and heap pages are set up
    // once, not per child. A runner that crashes or times out costs the child it was running
    // only; the next child gets a fresh runner. For one submission's renders, never for
    // submissions of a batch. SHADOWLAB_GRADER_RUNNERS=0 turns it off.
    bool reuseProcesses = false;
};

// Every child runs with MESA_SHADER_CACHE_DISABLE=true (Mesa's cache is the only file a
// render would write outside OUT) unless its `env` turns the cache on in a folder of its own
// (a grade's workers share one inside OUT), and in its own process group.

// Runs `load` (loading a shared library every worker needs, such as the image codec) and counts
// the threads it leaves behind as idle library threads, like those started before main(), so
// that workers are still forked without exec after it.
void loadBeforeForking(const std::function<void()>& load);

// The path of the running executable (/proc/self/exe): workers are this binary.
std::string selfExecutable();

// The first timeout of each group: children of a timed-out group are not started.
using TimedOutGroups = std::map<std::string, ChildResult>;

// Runs every spec, at most `parallel` at a time; `done(i, result)` is called as each ends,
// after the children that take the freed places have started (it may do slow work).
// `timedOut`, if given, carries the groups' timeouts from one call to the next.
std::vector<ChildResult> runChildren(const std::vector<ChildSpec>& specs, const Limits& limits,
                                     int parallel,
                                     const std::function<void(size_t, const ChildResult&)>& done = {},
                                     TimedOutGroups* timedOut = nullptr);

std::string signalName(int signal);  // "SIGSEGV (Segmentation fault)"

}  // namespace sl::grader
