// isolation: one child process per (scene, stage) render, so that a student's infinite loop,
// crash or runaway allocation costs that stage only. Each child is this executable run with the
// hidden `grade-worker` subcommand (fork + exec: a fresh process with no GL state inherited),
// in its own process group (a timeout kills llvmpipe's threads and anything it started), with
// RLIMIT_AS as the memory limit and PR_SET_PDEATHSIG so that it cannot outlive the grader.
// A worker is forked without exec while the grader has one thread (ChildSpec::run): the same
// fresh GL state, without re-linking the program's libraries; with Limits::reuseProcesses such
// children run one after another in runners (runner_pool).
#include "isolation.h"
#include "child_setup.h"
#include "runner_pool.h"

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

#include <chrono>
#include <fstream>
#include <map>
#include <thread>

namespace sl::grader {
namespace {

using Clock = std::chrono::steady_clock;

struct Running {
    size_t index;
    pid_t pid;
    Clock::time_point start;
    int runner = -1;  // the runner it runs in (Limits::reuseProcesses), -1: a child of its own
};

// The parent's environment with the child's settings (for execve).
std::vector<std::string> childEnvironment(const ChildSpec& spec) {
    const auto settings = childSettings(spec);
    std::vector<std::string> env;
    for (char** e = environ; e && *e; ++e) {
        const std::string_view v(*e);
        bool overridden = false;
        for (const auto& [name, value] : settings)
            overridden = overridden || v.starts_with(name + "=");
        if (!overridden) env.emplace_back(v);
    }
    for (const auto& [name, value] : settings) env.push_back(name + "=" + value);
    return env;
}

pid_t startChild(const ChildSpec& spec, const Limits& limits, const std::string& exe) {
    const std::string log = spec.logPath.string();
    if (spec.run && forkIsSafe()) {
        prepareFork();
        pid_t pid = ::fork();
        if (pid != 0) return pid;
        setUpChild(limits, log.c_str());
        applySettings(childSettings(spec));
        ::_exit(runJob(spec));  // not the grader's exit handlers or destructors
    }
    std::vector<std::string> env = childEnvironment(spec);
    std::vector<char*> cenv;
    for (auto& e : env) cenv.push_back(e.data());
    cenv.push_back(nullptr);
    std::vector<std::string> argv = {exe};
    argv.insert(argv.end(), spec.args.begin(), spec.args.end());
    std::vector<char*> cargv;
    for (auto& a : argv) cargv.push_back(a.data());
    cargv.push_back(nullptr);
    pid_t pid = ::fork();
    if (pid != 0) return pid;
    // Child of a threaded process: only async-signal-safe calls until exec.
    setUpChild(limits, log.c_str());
    // /proc/self/exe, not its path: the build may have replaced the file since we started.
    ::execve("/proc/self/exe", cargv.data(), cenv.data());
    ::execve(cargv[0], cargv.data(), cenv.data());
    ::_exit(127);
}

std::string readLog(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::string s(64 * 1024, '\0');
    in.read(s.data(), std::streamsize(s.size()));
    s.resize(size_t(in.gcount()));
    return s;
}

void replaceAll(std::string& s, const std::string& from, const std::string& to) {
    if (from.empty()) return;
    for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
        s.replace(at, from.size(), to);
}

}  // namespace

std::string selfExecutable() {
    char buf[4096];
    ssize_t n = ::readlink("/proc/self/exe", buf, sizeof buf - 1);
    if (n <= 0) return "shadowlab";
    return std::string(buf, size_t(n));
}

std::string signalName(int sig) {
    const char* abbrev = ::sigabbrev_np(sig);
    const char* text = ::strsignal(sig);
    std::string s = abbrev ? std::string("SIG") + abbrev : "signal " + std::to_string(sig);
    if (text) s += std::string(" (") + text + ")";
    return s;
}

std::vector<ChildResult> runChildren(const std::vector<ChildSpec>& specs, const Limits& limits,
                                     int parallel,
                                     const std::function<void(size_t, const ChildResult&)>& done,
                                     TimedOutGroups* timedOut) {
    std::vector<ChildResult> results(specs.size());
    const std::string exe = selfExecutable();
    std::vector<Running> running;
    const bool reuse = limits.reuseProcesses && !RunnerPool::turnedOff();
    RunnerPool pool(specs, limits, parallel);
    size_t next = 0;
    auto limitOf = [&](size_t i) {
        return specs[i].timeoutSeconds > 0 ? specs[i].timeoutSeconds : limits.timeoutSeconds;
    };
    TimedOutGroups own;
    TimedOutGroups& timedOutGroups = timedOut ? *timedOut : own;
    // The first timed-out group among those a child also runs and its own: the stages it runs
    // first, as they are what loops when both timed out (a loop in moments.glsl stops the
    // moments render and the final alike; either may end first).
    auto timedOutBefore = [&](const ChildSpec& spec) -> const TimedOutGroups::value_type* {
        std::vector<std::string> groups = spec.alsoRuns;
        groups.push_back(spec.group);
        for (const auto& g : groups)
            if (auto t = timedOutGroups.find(g); !g.empty() && t != timedOutGroups.end()) return &*t;
        return nullptr;
    };
    std::vector<size_t> ended;  // not yet handed to `done`
    // Starts children up to `parallel`.
    auto startMore = [&] {
        while (next < specs.size() && int(running.size()) < std::max(1, parallel)) {
            if (const auto* t = timedOutBefore(specs[next])) {
                results[next] = t->second;  // the same reason, without the same wait
                results[next].skipped = true;
                results[next].skippedAfter = t->first == specs[next].group ? "" : t->first;
                results[next].log.clear();
                ended.push_back(next);
                ++next;
                continue;
            }
            if (specs[next].skipIf && specs[next].skipIf()) {
                results[next].notRun = true;
                ended.push_back(next);
                ++next;
                continue;
            }
            results[next].limitSeconds = limitOf(next);
            results[next].limitNote = specs[next].limitNote;
            if (reuse && specs[next].run) {
                if (const int slot = pool.send(next); slot >= 0) {
                    running.push_back({next, pool.pid(slot), Clock::now(), slot});
                    ++next;
                    continue;
                }
            }
            pid_t pid = startChild(specs[next], limits, exe);
            if (pid < 0) {
                results[next].kind = ChildResult::StartFailed;
                ended.push_back(next);
            } else {
                running.push_back({next, pid, Clock::now()});
            }
            ++next;
        }
    };
    // The next children first: `done` may take a while (the grader scores there), and the
    // free places should not wait for it.
    auto handOver = [&] {
        startMore();
        std::vector<size_t> now;
        now.swap(ended);
        if (done)
            for (size_t i : now) done(i, results[i]);
    };
    // How a child (or the runner it ran in) ended: over time (w == 0) the whole group is
    // killed and reaped; else its wait status. The CPU is its rusage.
    auto settle = [](ChildResult& res, pid_t pid, pid_t w, int status, struct rusage& usage) {
        if (w == 0) {
            ::kill(-pid, SIGKILL);
            ::wait4(pid, &status, 0, &usage);
            res.kind = ChildResult::TimedOut;
        } else if (WIFSIGNALED(status)) {
            res.kind = ChildResult::Signalled;
            res.signal = WTERMSIG(status);
        } else {
            res.kind = ChildResult::Exited;
            res.exitCode = WEXITSTATUS(status);
        }
        res.cpuSeconds = cpuSecondsOf(usage);
    };
    bool progressed = false;
    // A child has ended: its time and log, its group's timeout, and it leaves `running`.
    auto finish = [&](size_t k, ChildResult& res, Clock::duration elapsed) {
        const size_t index = running[k].index;
        res.seconds = std::chrono::duration<double>(elapsed).count();
        res.log = readLog(specs[index].logPath);
        for (const auto& [from, to] : specs[index].scrub) replaceAll(res.log, from, to);
        if (res.kind == ChildResult::TimedOut && !specs[index].group.empty())
            timedOutGroups.emplace(specs[index].group, res);
        ended.push_back(index);
        running.erase(running.begin() + std::ptrdiff_t(k));
        progressed = true;
    };
    while (next < specs.size() || !running.empty()) {
        handOver();
        progressed = false;
        for (size_t k = 0; k < running.size();) {
            Running& r = running[k];
            if (r.runner >= 0) {
                ChildResult& res = results[r.index];
                const auto elapsed = Clock::now() - r.start;
                RunnerPool::Poll p = pool.poll(r.runner);
                if (!p.acked && p.waited == 0 && elapsed < std::chrono::duration<double>(limitOf(r.index))) {
                    ++k;
                    continue;
                }
                if (p.acked) {
                    res.kind = ChildResult::Exited;
                    res.exitCode = p.code;
                    res.cpuSeconds = p.cpuSeconds;
                    pool.idle(r.runner);
                } else {
                    settle(res, r.pid, p.waited, p.status, p.usage);
                    pool.stop(r.runner);
                }
                finish(k, res, elapsed);
                continue;
            }
            int status = 0;
            struct rusage usage {};
            pid_t w = ::wait4(r.pid, &status, WNOHANG, &usage);
            const auto elapsed = Clock::now() - r.start;
            ChildResult& res = results[r.index];
            if (w == 0 && elapsed < std::chrono::duration<double>(limitOf(r.index))) {
                ++k;
                continue;
            }
            settle(res, r.pid, w, status, usage);
            ::kill(-r.pid, SIGKILL);  // leftovers of the group, if any
            finish(k, res, elapsed);
        }
        if (!progressed) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    handOver();  // the last ones
    return results;  // the pool's runners end at the end of their jobs
}

}  // namespace sl::grader
