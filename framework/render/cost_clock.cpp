// cost_clock: the two cost clocks (see cost_clock.h).
#include "cost_clock.h"

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <stdexcept>
#include <thread>

// Callgrind's triggers (tools/cost_exact.sh: --zero-before, --dump-after). Not inlined, not
// folded together, and C names, so that callgrind finds them by name.
extern "C" {
__attribute__((noinline)) void shadowlab_cost_zero() { asm volatile("" ::: "memory"); }
__attribute__((noinline)) void shadowlab_cost_dump() { asm volatile("nop" ::: "memory"); }
}

namespace sl {
namespace {

bool countInstructions() {
    static const bool on = [] {
        const char* c = std::getenv("SHADOWLAB_COST");
        return c && std::string(c) == "instructions";
    }();
    return on;
}

double cpuStart = 0.0;
int dumps = 0;  // callgrind numbers its dumps 1, 2, ... after --callgrind-out-file's name

// The instructions of callgrind's latest dump ("totals: N"), in millions.
double readDump() {
    const char* out = std::getenv("SHADOWLAB_CALLGRIND_OUT");
    if (!out || !*out)
        throw std::runtime_error("SHADOWLAB_COST=instructions needs SHADOWLAB_CALLGRIND_OUT (the "
                                 "--callgrind-out-file callgrind writes): run under tools/cost_exact.sh");
    const std::string path = std::string(out) + "." + std::to_string(++dumps);
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);)
        if (line.rfind("totals:", 0) == 0) {
            in.close();
            std::remove(path.c_str());  // read once; a study makes thousands
            return std::stod(line.substr(7)) * 1e-6;
        }
    throw std::runtime_error(path + ": no callgrind dump with totals (is the program running "
                             "under tools/cost_exact.sh?)");
}

}  // namespace

double processCpuMillis() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

void costBegin() {
    if (countInstructions()) shadowlab_cost_zero();
    else cpuStart = processCpuMillis();
}

double costEnd() {
    if (!countInstructions()) return processCpuMillis() - cpuStart;
    shadowlab_cost_dump();
    return readDump();
}

std::string costMethod() {
    const char* threads = std::getenv("LP_NUM_THREADS");
    const std::string n = threads && *threads
                              ? std::string(threads)
                              : std::to_string(std::thread::hardware_concurrency()) + " (default)";
    if (countInstructions())
        return "million instructions: all threads, counted by callgrind around glFinish, "
               "LP_NUM_THREADS=" + n;
    return "CPU ms: process CPU time (all threads) around glFinish, LP_NUM_THREADS=" + n;
}

}  // namespace sl
