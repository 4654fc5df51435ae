// cost_clock: what a pass costs, measured so that the host's load moves it as little as
// possible: the cost axis of `shadowlab study` and `shadowlab bench`. Two clocks:
// - "cpu" (default): the CPU time of every thread of the process (CLOCK_PROCESS_CPUTIME_ID: the
//   user + system time getrusage reports, in nanoseconds) around the pass's glFinish. llvmpipe
//   runs a pass on its own LP_NUM_THREADS threads while the caller waits, so this is the work
//   the pass took; time spent waiting for a core another process holds is not in it.
// - "instructions" (SHADOWLAB_COST=instructions, run under tools/cost_exact.sh): the
//   instructions every thread executed, counted by valgrind's callgrind (millions), which no
//   other process can change. The clock calls two marker functions callgrind is told about
//   (zero the counts before one, dump them after the other) and reads the dump back.
// - "cycles" (SHADOWLAB_COST=cycles, tools/cost_exact.sh --cycles): the same with callgrind's
//   cache simulation, as its cycle estimate (instructions + 10 per first-level miss + 100 per
//   last-level miss, caches of a fixed size): exact too, and it sees memory traffic, which the
//   instruction count does not (a lookup far apart in a large table costs misses, not work).
// Measurements must not nest: one begin, one end.
#pragma once

#include <string>

namespace sl {

// CPU time of every thread of this process so far, in milliseconds.
double processCpuMillis();

// Start measuring (before the work is issued; the caller has glFinished what came before).
void costBegin();
// The cost since costBegin (after the work's glFinish): CPU ms, or millions of instructions
// (or estimated cycles).
double costEnd();

// "CPU ms: process CPU time (all threads) around glFinish, LP_NUM_THREADS=2", or the
// instructions' equivalent: the unit and the method, for the output that reports a cost
// (llvmpipe's CPU time grows with the threads it keeps busy, so figures compare at one count).
std::string costMethod();

// The unit of costEnd's figures, short, for a column: "CPU ms", "M instr" or "M cycles".
std::string costUnit();

// True under tools/cost_exact.sh without --cycles: costs are instructions, the clock the
// bench's goals are stated on.
bool costCountsInstructions();

}  // namespace sl
