// phase_clock.h: where a grade's CPU goes. With SHADOWLAB_GRADER_TIMING=1 each lap prints one
// line on stderr, "phase <process> <what>: <wall> s wall, <user> s user, <sys> s sys", the CPU
// of this process since the last lap (the first lap: since the process started, so a worker's
// "start" is its fork or exec; in a runner, since its job began: jobStarts). A grade's workers write theirs to their logs;
// tools/grade_phases.sh adds them up into the table of docs/performance.md.
#pragma once

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <sys/resource.h>

namespace sl::grader {

class PhaseClock {
public:
    explicit PhaseClock(std::string process)
        : process_(std::move(process)), on_(std::getenv("SHADOWLAB_GRADER_TIMING") != nullptr),
          user_(jobUser_), sys_(jobSys_) {}
    // A runner calls this as each job begins, with its CPU clock then (grader/intake/runner_pool.cpp):
    // the job's first lap counts from here, not from the runner's start with every earlier job in it.
    static void jobStarts(const struct rusage& u) { jobUser_ = seconds(u.ru_utime), jobSys_ = seconds(u.ru_stime); }
    void lap(const char* what) {
        if (!on_) return;
        struct rusage u {};
        ::getrusage(RUSAGE_SELF, &u);
        const double user = seconds(u.ru_utime), sys = seconds(u.ru_stime);
        const auto now = std::chrono::steady_clock::now();
        std::fprintf(stderr, "phase %s %s: %.4f s wall, %.4f s user, %.4f s sys\n", process_.c_str(), what,
                     std::chrono::duration<double>(now - wall_).count(), user - user_, sys - sys_);
        std::fflush(stderr);
        user_ = user, sys_ = sys, wall_ = now;
    }

private:
    static double seconds(const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); }
    std::string process_;
    bool on_;
    double user_, sys_;
    static inline double jobUser_ = 0.0, jobSys_ = 0.0;
    std::chrono::steady_clock::time_point wall_ = std::chrono::steady_clock::now();
};

}  // namespace sl::grader
