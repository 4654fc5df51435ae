// cpu_clock: the process's CPU time, the cost axis of `shadowlab study` and `shadowlab bench`.
// llvmpipe does a pass's work on its own threads (LP_NUM_THREADS of them) while the caller
// waits in glFinish; the CPU time of all the process's threads around that glFinish is the
// work the pass took, and unlike wall time it does not grow when another process holds a core
// (waiting for a core is not CPU time). It is what getrusage(RUSAGE_SELF) reports as user +
// system time, read from the clock that has nanoseconds rather than getrusage's ticks.
#pragma once

#include <cstdlib>
#include <ctime>
#include <string>
#include <thread>

namespace sl {

// CPU time of every thread of this process so far, in milliseconds.
inline double processCpuMillis() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

// "process CPU time (all threads) around glFinish, LP_NUM_THREADS=2": what a cost measured with
// processCpuMillis is, with llvmpipe's thread count (its CPU time grows with the threads it
// keeps busy, so figures compare at one count), for the output that reports it.
inline std::string cpuCostMethod() {
    const char* threads = std::getenv("LP_NUM_THREADS");
    const std::string n = threads && *threads
                              ? std::string(threads)
                              : std::to_string(std::thread::hardware_concurrency()) + " (default)";
    return "process CPU time (all threads) around glFinish, LP_NUM_THREADS=" + n;
}

}  // namespace sl
