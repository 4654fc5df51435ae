// isolation: one child process per (scene, stage) render, so that a student's infinite loop,
// crash or runaway allocation costs that stage only. Each child is this executable run with the
// hidden `grade-worker` subcommand (fork + exec: a fresh process with no GL state inherited),
// in its own process group (a timeout kills llvmpipe's threads and anything it started), with
// RLIMIT_AS as the memory limit and PR_SET_PDEATHSIG so that it cannot outlive the grader.
// A worker is forked without exec while the grader has one thread (ChildSpec::run): the same
// fresh GL state, without re-linking the program's libraries.
#include "isolation.h"
#include "phase_clock.h"

#include <fcntl.h>
#include <malloc.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
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

// A runner: a forked child that runs the `run` of one spec after another, each job's index
// sent down `jobs` and its exit code and CPU seconds sent back up `acks`.
// It takes only jobs whose settings (childSettings) equal those of its first: the driver reads
// some of them once per process, and a job must not inherit another's.
struct Runner {
    pid_t pid = -1;
    int jobs = -1, acks = -1;
    bool busy = false;
    std::vector<std::pair<std::string, std::string>> settings;
};

struct Ack {
    int code;
    double cpuSeconds;
};

double cpuSecondsOf(const rusage& u) {
    auto secs = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
    return secs(u.ru_utime) + secs(u.ru_stime);
}

// The cache settings every child gets, then the spec's own (`env`).
std::vector<std::pair<std::string, std::string>> childSettings(const ChildSpec& spec) {
    std::vector<std::pair<std::string, std::string>> set = {
        {"MESA_SHADER_CACHE_DISABLE", "true"},
        {"MESA_GLSL_CACHE_DISABLE", "true"}};  // Mesa before 22.1
    for (const auto& kv : spec.env) {
        std::erase_if(set, [&](const auto& s) { return s.first == kv.first; });
        set.push_back(kv);
    }
    return set;
}

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

// The threads of this process, by id.
std::set<std::string> threadIds() {
    std::set<std::string> ids;
    std::error_code ec;
    for (auto it = std::filesystem::directory_iterator("/proc/self/task", ec);
         !ec && it != std::filesystem::directory_iterator(); it.increment(ec))
        ids.insert(it->path().filename().string());
    return ec ? std::set<std::string>{} : ids;
}

// The threads running before main(), and those loadBeforeForking saw start: log4cplus, which
// the image libraries link, starts an idle pool while it loads. A static of the executable, so
// initialised after every library's.
std::set<std::string> kStartupThreads = threadIds();

// fork without exec is safe while no thread but the calling one and those idle library
// threads (which a worker never calls) exists: any other (a GL context's, an image library's
// pool) could hold a lock the child needs, locked forever there. The calling thread is the
// main one, or in a forked child (a batch's grade) the only one, which has a new id.
bool forkIsSafe() {
    auto now = threadIds();
    if (now.empty()) return false;
    now.erase(std::to_string(::gettid()));
    for (const auto& id : now)
        if (!kStartupThreads.count(id)) return false;
    return true;
}

}  // namespace

void loadBeforeForking(const std::function<void()>& load) {
    const auto before = threadIds();
    load();
    for (const auto& id : threadIds())
        if (!before.count(id)) kStartupThreads.insert(id);
}

namespace {

// In a new child, before its work: own process group, dies with the grader, limits, log.
void setUpChild(const Limits& limits, const char* log) {
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (limits.memoryMb > 0) {
        rlimit rl{};
        rl.rlim_cur = rl.rlim_max = rlim_t(limits.memoryMb) * 1024 * 1024;
        ::setrlimit(RLIMIT_AS, &rl);
    }
    rlimit core{0, 0};  // a crashing shader compiler must not leave core files behind
    ::setrlimit(RLIMIT_CORE, &core);
    int fd = ::open(log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
        ::dup2(fd, 1);
        ::dup2(fd, 2);
        ::close(fd);
    }
}

// The runner's loop: each job's log on its stdout and stderr, its `run`, then the ack (its
// settings are the runner's, set once by startRunner). Ends (exit 0) when the job pipe closes.
[[noreturn]] void runnerLoop(const std::vector<ChildSpec>& specs, int jobs, int acks) {
    // Freed heap pages stay for the next job (no trim, no mmap for a map-sized block): the
    // kernel zeroes each page once per runner instead of once per render.
    ::mallopt(M_TRIM_THRESHOLD, 1 << 30);
    ::mallopt(M_MMAP_THRESHOLD, 32 << 20);
    for (;;) {
        std::uint32_t index = 0;
        if (::read(jobs, &index, sizeof index) != ssize_t(sizeof index) || index >= specs.size()) ::_exit(0);
        const ChildSpec& spec = specs[index];
        int fd = ::open(spec.logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            ::dup2(fd, 1);
            ::dup2(fd, 2);
            ::close(fd);
        }
        rusage before{}, after{};
        ::getrusage(RUSAGE_SELF, &before);
        PhaseClock::jobStarts(before);
        Ack ack{1, 0.0};
        try {
            ack.code = spec.run();
        } catch (...) {
        }
        std::cout.flush();
        std::cerr.flush();
        std::fflush(nullptr);
        ::getrusage(RUSAGE_SELF, &after);
        ack.cpuSeconds = cpuSecondsOf(after) - cpuSecondsOf(before);
        if (::write(acks, &ack, sizeof ack) != ssize_t(sizeof ack)) ::_exit(1);
    }
}

// Forks a runner for `specs` with `settings` in its environment (the caller checked
// forkIsSafe); false if it could not. The runner closes the other runners' pipe ends: a copy
// of another's job pipe held open would keep that runner from ever seeing its end of jobs.
bool startRunner(Runner& r, const std::vector<Runner>& others, const std::vector<ChildSpec>& specs,
                 const Limits& limits, const std::vector<std::pair<std::string, std::string>>& settings) {
    int jobs[2], acks[2];
    if (::pipe2(jobs, O_CLOEXEC) != 0) return false;
    if (::pipe2(acks, O_CLOEXEC) != 0) {
        ::close(jobs[0]), ::close(jobs[1]);
        return false;
    }
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    ::malloc_trim(0);
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::close(jobs[1]), ::close(acks[0]);
        for (const Runner& o : others)
            if (o.pid > 0) ::close(o.jobs), ::close(o.acks);
        setUpChild(limits, "/dev/null");
        for (const auto& [name, value] : settings) ::setenv(name.c_str(), value.c_str(), 1);
        runnerLoop(specs, jobs[0], acks[1]);
    }
    ::close(jobs[0]), ::close(acks[1]);
    if (pid < 0) {
        ::close(jobs[1]), ::close(acks[0]);
        return false;
    }
    ::fcntl(acks[0], F_SETFL, O_NONBLOCK);
    r = {pid, jobs[1], acks[0], false, settings};
    return true;
}

// Closes a runner's pipes (a live one ends its loop at EOF, or is killed), reaps it unless
// `settle` already has, and kills what it left in its group.
void stopRunner(Runner& r, bool kill) {
    if (r.pid <= 0) return;
    ::close(r.jobs), ::close(r.acks);
    if (kill) ::kill(-r.pid, SIGKILL);
    int status = 0;
    ::waitpid(r.pid, &status, 0);  // ECHILD if already reaped
    ::kill(-r.pid, SIGKILL);  // anything the runner left in its group
    r = Runner();
}

bool runnersOff() {
    const char* v = std::getenv("SHADOWLAB_GRADER_RUNNERS");
    return v && std::string(v) == "0";
}

pid_t startChild(const ChildSpec& spec, const Limits& limits, const std::string& exe) {
    const std::string log = spec.logPath.string();
    if (spec.run && forkIsSafe()) {
        // Buffered output would be written twice (by the parent and by the child).
        std::cout.flush();
        std::cerr.flush();
        std::fflush(nullptr);
        // Free heap pages go back to the kernel first: a child reusing them would copy each on
        // its first write (copy-on-write), where a fresh page costs only a fault.
        ::malloc_trim(0);
        pid_t pid = ::fork();
        if (pid != 0) return pid;
        setUpChild(limits, log.c_str());
        for (const auto& [name, value] : childSettings(spec)) ::setenv(name.c_str(), value.c_str(), 1);
        int code = 1;
        try {
            code = spec.run();
        } catch (...) {
        }
        std::cout.flush();
        std::cerr.flush();
        std::fflush(nullptr);
        ::_exit(code);  // not the grader's exit handlers or destructors
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
    std::vector<Runner> runners(size_t(std::max(1, parallel)));
    const bool reuse = limits.reuseProcesses && !runnersOff();
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
                // An idle runner with this job's settings, else a new one in a free slot, else
                // a new one in place of an idle runner with other settings.
                const auto settings = childSettings(specs[next]);
                int slot = -1;
                for (size_t k = 0; k < runners.size() && slot < 0; ++k)
                    if (runners[k].pid > 0 && !runners[k].busy && runners[k].settings == settings) slot = int(k);
                auto start = [&](size_t k) {
                    if (!forkIsSafe() || !startRunner(runners[k], runners, specs, limits, settings)) return;
                    slot = int(k);
                };
                for (size_t k = 0; k < runners.size() && slot < 0; ++k)
                    if (runners[k].pid <= 0) start(k);
                for (size_t k = 0; k < runners.size() && slot < 0; ++k)
                    if (runners[k].pid > 0 && !runners[k].busy) {
                        stopRunner(runners[k], true);
                        start(k);
                    }
                const std::uint32_t index = std::uint32_t(next);
                if (slot >= 0 && ::write(runners[size_t(slot)].jobs, &index, sizeof index) == ssize_t(sizeof index)) {
                    runners[size_t(slot)].busy = true;
                    running.push_back({next, runners[size_t(slot)].pid, Clock::now(), slot});
                    ++next;
                    continue;
                }
                if (slot >= 0) stopRunner(runners[size_t(slot)], true);
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
                Runner& runner = runners[size_t(r.runner)];
                ChildResult& res = results[r.index];
                const auto elapsed = Clock::now() - r.start;
                Ack ack{};
                const bool acked = ::read(runner.acks, &ack, sizeof ack) == ssize_t(sizeof ack);
                int status = 0;
                struct rusage usage {};
                const pid_t w = acked ? 0 : ::wait4(runner.pid, &status, WNOHANG, &usage);
                if (!acked && w == 0 && elapsed < std::chrono::duration<double>(limitOf(r.index))) {
                    ++k;
                    continue;
                }
                if (acked) {
                    res.kind = ChildResult::Exited;
                    res.exitCode = ack.code;
                    res.cpuSeconds = ack.cpuSeconds;
                    runner.busy = false;
                } else {
                    settle(res, runner.pid, w, status, usage);
                    stopRunner(runner, true);
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
    for (auto& runner : runners) stopRunner(runner, false);  // EOF: each ends its loop
    return results;
}

}  // namespace sl::grader
