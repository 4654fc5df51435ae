// runner_pool: runners, forked children that run one grader job after another.
#include "runner_pool.h"
#include "phase_clock.h"

#include <fcntl.h>
#include <malloc.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>

namespace sl::grader {
namespace {

struct Ack {
    int code;
    double cpuSeconds;
};

// The runner's loop: each job's log on its stdout and stderr, its `run`, then the ack (its
// settings are the runner's, set once when it started). Ends (exit 0) when the job pipe closes.
[[noreturn]] void runnerLoop(const std::vector<ChildSpec>& specs, int jobs, int acks) {
    // Freed heap pages stay for the next job (no trim, no mmap for a map-sized block): the
    // kernel zeroes each page once per runner instead of once per render.
    ::mallopt(M_TRIM_THRESHOLD, 1 << 30);
    ::mallopt(M_MMAP_THRESHOLD, 32 << 20);
    for (;;) {
        std::uint32_t index = 0;
        if (::read(jobs, &index, sizeof index) != ssize_t(sizeof index) || index >= specs.size()) ::_exit(0);
        const ChildSpec& spec = specs[index];
        redirectOutput(spec.logPath.c_str());
        rusage before{}, after{};
        ::getrusage(RUSAGE_SELF, &before);
        PhaseClock::jobStarts(before);
        Ack ack{runJob(spec), 0.0};
        ::getrusage(RUSAGE_SELF, &after);
        ack.cpuSeconds = cpuSecondsOf(after) - cpuSecondsOf(before);
        if (::write(acks, &ack, sizeof ack) != ssize_t(sizeof ack)) ::_exit(1);
    }
}

}  // namespace

RunnerPool::RunnerPool(const std::vector<ChildSpec>& specs, const Limits& limits, int size)
    : specs_(specs), limits_(limits), runners_(size_t(std::max(1, size))) {}

RunnerPool::~RunnerPool() {
    for (size_t k = 0; k < runners_.size(); ++k) stop(int(k), false);
}

bool RunnerPool::turnedOff() {
    const char* v = std::getenv("SHADOWLAB_GRADER_RUNNERS");
    return v && std::string(v) == "0";
}

// Forks a runner with `settings` in its environment; false if it could not. The runner closes
// the other runners' pipe ends: a copy of another's job pipe held open would keep that runner
// from ever seeing the end of its jobs.
bool RunnerPool::start(size_t slot, const ChildSettings& settings) {
    if (!forkIsSafe()) return false;
    int jobs[2], acks[2];
    if (::pipe2(jobs, O_CLOEXEC) != 0) return false;
    if (::pipe2(acks, O_CLOEXEC) != 0) {
        ::close(jobs[0]), ::close(jobs[1]);
        return false;
    }
    prepareFork();
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::close(jobs[1]), ::close(acks[0]);
        for (const Runner& o : runners_)
            if (o.pid > 0) ::close(o.jobs), ::close(o.acks);
        setUpChild(limits_, "/dev/null");
        applySettings(settings);
        runnerLoop(specs_, jobs[0], acks[1]);
    }
    ::close(jobs[0]), ::close(acks[1]);
    if (pid < 0) {
        ::close(jobs[1]), ::close(acks[0]);
        return false;
    }
    ::fcntl(acks[0], F_SETFL, O_NONBLOCK);
    runners_[slot] = {pid, jobs[1], acks[0], false, settings};
    return true;
}

int RunnerPool::send(size_t index) {
    const ChildSettings settings = childSettings(specs_[index]);
    int slot = -1;
    for (size_t k = 0; k < runners_.size() && slot < 0; ++k)
        if (runners_[k].pid > 0 && !runners_[k].busy && runners_[k].settings == settings) slot = int(k);
    for (size_t k = 0; k < runners_.size() && slot < 0; ++k)
        if (runners_[k].pid <= 0 && start(k, settings)) slot = int(k);
    for (size_t k = 0; k < runners_.size() && slot < 0; ++k)
        if (runners_[k].pid > 0 && !runners_[k].busy) {
            stop(int(k));
            if (start(k, settings)) slot = int(k);
        }
    if (slot < 0) return -1;
    Runner& r = runners_[size_t(slot)];
    const std::uint32_t job = std::uint32_t(index);
    if (::write(r.jobs, &job, sizeof job) != ssize_t(sizeof job)) {
        stop(slot);
        return -1;
    }
    r.busy = true;
    return slot;
}

RunnerPool::Poll RunnerPool::poll(int slot) {
    Runner& r = runners_[size_t(slot)];
    Poll p;
    Ack ack{};
    p.acked = ::read(r.acks, &ack, sizeof ack) == ssize_t(sizeof ack);
    if (p.acked) {
        p.code = ack.code;
        p.cpuSeconds = ack.cpuSeconds;
    } else {
        p.waited = ::wait4(r.pid, &p.status, WNOHANG, &p.usage);
    }
    return p;
}

void RunnerPool::stop(int slot, bool kill) {
    Runner& r = runners_[size_t(slot)];
    if (r.pid <= 0) return;
    ::close(r.jobs), ::close(r.acks);
    if (kill) ::kill(-r.pid, SIGKILL);
    int status = 0;
    ::waitpid(r.pid, &status, 0);  // ECHILD if already reaped
    ::kill(-r.pid, SIGKILL);       // anything the runner left in its group
    r = Runner();
}

}  // namespace sl::grader
