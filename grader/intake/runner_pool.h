// runner_pool: forked children that run one job after another (Limits::reuseProcesses): the
// driver, the libraries and the heap pages the kernel zeroed are set up once per runner, not
// once per render. A runner that crashes or times out costs the job it ran; the next job gets
// a fresh runner. A runner takes only jobs whose settings (childSettings) equal those it
// started with: the driver reads some of them once per process, and a job must not inherit
// another's. SHADOWLAB_GRADER_RUNNERS=0 turns runners off.
#pragma once

#include "child_setup.h"

#include <sys/types.h>

#include <vector>

namespace sl::grader {

class RunnerPool {
public:
    // At most `size` runners for the jobs `specs` (each a spec with a `run`).
    RunnerPool(const std::vector<ChildSpec>& specs, const Limits& limits, int size);
    ~RunnerPool();  // each runner sees the end of its jobs, ends its loop and is reaped
    RunnerPool(const RunnerPool&) = delete;
    RunnerPool& operator=(const RunnerPool&) = delete;

    static bool turnedOff();  // SHADOWLAB_GRADER_RUNNERS=0

    // Hands job `index` to an idle runner with its settings, else to a new one in a free place,
    // else to a new one in place of an idle runner with other settings: the runner's slot, or
    // -1 when none could take it (the caller starts a child of its own).
    int send(size_t index);
    pid_t pid(int slot) const { return runners_[size_t(slot)].pid; }

    // How the job in `slot` stands: acked (its exit code and CPU seconds), or not acked and
    // `waited` is wait4's answer for the runner (0: still running; else `status` and `usage`).
    struct Poll {
        bool acked = false;
        int code = 1;
        double cpuSeconds = 0.0;
        pid_t waited = 0;
        int status = 0;
        struct rusage usage {};
    };
    Poll poll(int slot);
    void idle(int slot) { runners_[size_t(slot)].busy = false; }  // after an ack
    // Closes the runner's pipes, kills it if `kill` (else it ends at the end of its jobs), reaps
    // it unless wait4 already has, and kills what it left in its group.
    void stop(int slot, bool kill = true);

private:
    struct Runner {
        pid_t pid = -1;
        int jobs = -1, acks = -1;  // the job indices go down `jobs`, the acks come up `acks`
        bool busy = false;
        ChildSettings settings;
    };
    bool start(size_t slot, const ChildSettings& settings);

    const std::vector<ChildSpec>& specs_;
    Limits limits_;
    std::vector<Runner> runners_;
};

}  // namespace sl::grader
