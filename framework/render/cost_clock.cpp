// cost_clock: the two cost clocks (see cost_clock.h).
#include "cost_clock.h"

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

// Callgrind's triggers (tools/cost_exact.sh: --zero-before, --dump-after). Not inlined, not
// folded together, and C names, so that callgrind finds them by name.
extern "C" {
__attribute__((noinline)) void shadowlab_cost_zero() { asm volatile("" ::: "memory"); }
__attribute__((noinline)) void shadowlab_cost_dump() { asm volatile("nop" ::: "memory"); }
}

namespace sl {
namespace {

// "instructions" or "cycles" (both under callgrind), else "" (the CPU clock).
const std::string& exactClock() {
    static const std::string clock = [] {
        const char* c = std::getenv("SHADOWLAB_COST");
        const std::string s = c ? c : "";
        return s == "instructions" || s == "cycles" ? s : std::string();
    }();
    return clock;
}
bool countInstructions() { return !exactClock().empty(); }

// Callgrind's cycle estimate (KCachegrind's "CEst", without branch simulation): an instruction
// costs 1, a miss of a first-level cache 10 more, a miss of the last level 100 more. The caches
// are simulated with a fixed geometry (tools/cost_exact.sh), so the figure is the same on any
// CPU model; unlike the instruction count it sees where the data lies.
double cycleEstimate(const std::vector<std::string>& events, const std::vector<double>& totals) {
    double cost = 0.0;
    for (size_t i = 0; i < events.size() && i < totals.size(); ++i) {
        const std::string& e = events[i];
        if (e == "Ir") cost += totals[i];
        else if (e == "I1mr" || e == "D1mr" || e == "D1mw") cost += 10.0 * totals[i];
        else if (e == "ILmr" || e == "DLmr" || e == "DLmw") cost += 100.0 * totals[i];
    }
    return cost;
}

double cpuStart = 0.0;
int dumps = 0;  // callgrind numbers its dumps 1, 2, ... after --callgrind-out-file's name

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

// Callgrind's latest dump ("events: Ir ...", "totals: N ..."), in millions: its instructions,
// or with the cache simulation its cycle estimate.
double readDump() {
    const char* out = std::getenv("SHADOWLAB_CALLGRIND_OUT");
    if (!out || !*out)
        throw std::runtime_error("SHADOWLAB_COST=instructions needs SHADOWLAB_CALLGRIND_OUT (the "
                                 "--callgrind-out-file callgrind writes): run under tools/cost_exact.sh");
    const std::string path = std::string(out) + "." + std::to_string(++dumps);
    std::ifstream in(path);
    std::vector<std::string> events;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("events:", 0) == 0) events = words(line.substr(7));
        if (line.rfind("totals:", 0) != 0) continue;
        in.close();
        std::remove(path.c_str());  // read once; a study makes thousands
        std::vector<double> totals;
        for (const std::string& w : words(line.substr(7))) totals.push_back(std::stod(w));
        if (totals.empty()) break;
        if (exactClock() == "instructions") return totals[0] * 1e-6;
        if (events.size() < 2)
            throw std::runtime_error(path + ": SHADOWLAB_COST=cycles needs callgrind's cache "
                                     "simulation (tools/cost_exact.sh --cycles)");
        return cycleEstimate(events, totals) * 1e-6;
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

bool costCountsInstructions() { return exactClock() == "instructions"; }

std::string costUnit() {
    if (exactClock() == "instructions") return "M instr";
    if (exactClock() == "cycles") return "M cycles";
    return "CPU ms";
}

std::string costMethod() {
    const char* threads = std::getenv("LP_NUM_THREADS");
    const std::string n = threads && *threads
                              ? std::string(threads)
                              : std::to_string(std::thread::hardware_concurrency()) + " (default)";
    if (exactClock() == "instructions")
        return "million instructions: all threads, counted by callgrind around glFinish, "
               "LP_NUM_THREADS=" + n;
    if (exactClock() == "cycles")
        return "million estimated cycles: instructions + 10 per L1 miss + 100 per last-level "
               "miss, all threads, callgrind's cache simulation around glFinish, LP_NUM_THREADS=" +
               n;
    return "CPU ms: process CPU time (all threads) around glFinish, LP_NUM_THREADS=" + n;
}

}  // namespace sl
