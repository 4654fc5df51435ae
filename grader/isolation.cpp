// isolation: one child process per (scene, stage) render, so that a student's infinite loop,
// crash or runaway allocation costs that stage only. Each child is this executable run with the
// hidden `grade-worker` subcommand (fork + exec: a fresh process with no GL state inherited),
// in its own process group (a timeout kills llvmpipe's threads and anything it started), with
// RLIMIT_AS as the memory limit and PR_SET_PDEATHSIG so that it cannot outlive the grader.
#include "isolation.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

#include <chrono>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

namespace sl::grader {
namespace {

using Clock = std::chrono::steady_clock;

struct Running {
    size_t index;
    pid_t pid;
    Clock::time_point start;
};

// The parent's environment, with Mesa's on-disk shader cache turned off.
std::vector<std::string> childEnvironment() {
    std::vector<std::string> env;
    for (char** e = environ; e && *e; ++e) {
        const std::string_view v(*e);
        if (v.starts_with("MESA_SHADER_CACHE_DISABLE=") || v.starts_with("MESA_GLSL_CACHE_DISABLE="))
            continue;
        env.emplace_back(v);
    }
    env.push_back("MESA_SHADER_CACHE_DISABLE=true");
    env.push_back("MESA_GLSL_CACHE_DISABLE=true");  // Mesa before 22.1
    return env;
}

pid_t startChild(const ChildSpec& spec, const Limits& limits, const std::string& exe) {
    std::vector<std::string> env = childEnvironment();
    std::vector<char*> cenv;
    for (auto& e : env) cenv.push_back(e.data());
    cenv.push_back(nullptr);
    std::vector<std::string> argv = {exe};
    argv.insert(argv.end(), spec.args.begin(), spec.args.end());
    std::vector<char*> cargv;
    for (auto& a : argv) cargv.push_back(a.data());
    cargv.push_back(nullptr);
    const std::string log = spec.logPath.string();
    pid_t pid = ::fork();
    if (pid != 0) return pid;
    // Child: only async-signal-safe calls until exec.
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (limits.memoryMb > 0) {
        rlimit rl{};
        rl.rlim_cur = rl.rlim_max = rlim_t(limits.memoryMb) * 1024 * 1024;
        ::setrlimit(RLIMIT_AS, &rl);
    }
    rlimit core{0, 0};  // a crashing shader compiler must not leave core files behind
    ::setrlimit(RLIMIT_CORE, &core);
    int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
        ::dup2(fd, 1);
        ::dup2(fd, 2);
        ::close(fd);
    }
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
                                     const std::function<void(size_t, const ChildResult&)>& done) {
    std::vector<ChildResult> results(specs.size());
    const std::string exe = selfExecutable();
    std::vector<Running> running;
    size_t next = 0;
    auto limitOf = [&](size_t i) {
        return specs[i].timeoutSeconds > 0 ? specs[i].timeoutSeconds : limits.timeoutSeconds;
    };
    std::map<std::string, ChildResult> timedOutGroups;  // group -> the first timeout
    while (next < specs.size() || !running.empty()) {
        while (next < specs.size() && int(running.size()) < std::max(1, parallel)) {
            const std::string& group = specs[next].group;
            if (auto t = timedOutGroups.find(group); !group.empty() && t != timedOutGroups.end()) {
                results[next] = t->second;  // the same reason, without the same wait
                results[next].skipped = true;
                results[next].log.clear();
                if (done) done(next, results[next]);
                ++next;
                continue;
            }
            results[next].limitSeconds = limitOf(next);
            results[next].limitNote = specs[next].limitNote;
            pid_t pid = startChild(specs[next], limits, exe);
            if (pid < 0) {
                results[next].kind = ChildResult::StartFailed;
                if (done) done(next, results[next]);
            } else {
                running.push_back({next, pid, Clock::now()});
            }
            ++next;
        }
        bool progressed = false;
        for (size_t k = 0; k < running.size();) {
            Running& r = running[k];
            int status = 0;
            pid_t w = ::waitpid(r.pid, &status, WNOHANG);
            const auto elapsed = Clock::now() - r.start;
            ChildResult& res = results[r.index];
            if (w == 0 && elapsed < std::chrono::duration<double>(limitOf(r.index))) {
                ++k;
                continue;
            }
            if (w == 0) {  // over time: kill the whole group, then reap
                ::kill(-r.pid, SIGKILL);
                ::waitpid(r.pid, &status, 0);
                res.kind = ChildResult::TimedOut;
            } else if (WIFSIGNALED(status)) {
                res.kind = ChildResult::Signalled;
                res.signal = WTERMSIG(status);
            } else {
                res.kind = ChildResult::Exited;
                res.exitCode = WEXITSTATUS(status);
            }
            ::kill(-r.pid, SIGKILL);  // leftovers of the group, if any
            res.seconds = std::chrono::duration<double>(elapsed).count();
            res.log = readLog(specs[r.index].logPath);
            for (const auto& [from, to] : specs[r.index].scrub) replaceAll(res.log, from, to);
            if (res.kind == ChildResult::TimedOut && !specs[r.index].group.empty())
                timedOutGroups.emplace(specs[r.index].group, res);
            if (done) done(r.index, res);
            running.erase(running.begin() + std::ptrdiff_t(k));
            progressed = true;
        }
        if (!progressed) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return results;
}

}  // namespace sl::grader
