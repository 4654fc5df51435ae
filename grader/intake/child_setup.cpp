// child_setup: the settings, limits, log and fork checks every forked worker shares.
#include "child_setup.h"

#include <fcntl.h>
#include <malloc.h>
#include <signal.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <set>

namespace sl::grader {
namespace {

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

}  // namespace

ChildSettings childSettings(const ChildSpec& spec) {
    ChildSettings set = {{"MESA_SHADER_CACHE_DISABLE", "true"},
                         {"MESA_GLSL_CACHE_DISABLE", "true"}};  // Mesa before 22.1
    for (const auto& kv : spec.env) {
        std::erase_if(set, [&](const auto& s) { return s.first == kv.first; });
        set.push_back(kv);
    }
    return set;
}

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
    redirectOutput(log);
}

void redirectOutput(const char* log) {
    int fd = ::open(log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
        ::dup2(fd, 1);
        ::dup2(fd, 2);
        ::close(fd);
    }
}

void applySettings(const ChildSettings& settings) {
    for (const auto& [name, value] : settings) ::setenv(name.c_str(), value.c_str(), 1);
}

int runJob(const ChildSpec& spec) {
    int code = 1;
    try {
        code = spec.run();
    } catch (...) {
    }
    flushOutput();
    return code;
}

// Any thread but those (a GL context's, an image library's pool) could hold a lock the child
// needs, locked forever there. The calling thread is the main one, or in a forked child (a
// batch's grade) the only one, which has a new id.
bool forkIsSafe() {
    auto now = threadIds();
    if (now.empty()) return false;
    now.erase(std::to_string(::gettid()));
    for (const auto& id : now)
        if (!kStartupThreads.count(id)) return false;
    return true;
}

void loadBeforeForking(const std::function<void()>& load) {
    const auto before = threadIds();
    load();
    for (const auto& id : threadIds())
        if (!before.count(id)) kStartupThreads.insert(id);
}

void flushOutput() {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
}

void prepareFork() {
    flushOutput();
    ::malloc_trim(0);
}

double cpuSecondsOf(const rusage& u) {
    auto secs = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
    return secs(u.ru_utime) + secs(u.ru_stime);
}

}  // namespace sl::grader
