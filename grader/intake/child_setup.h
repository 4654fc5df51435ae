// child_setup: what every forked worker shares, whether a child of its own (isolation) or a
// runner (runner_pool): its settings, its limits and log, whether fork without exec is safe,
// and its CPU seconds.
#pragma once

#include "isolation.h"

#include <string>
#include <utility>
#include <vector>

#include <sys/resource.h>

namespace sl::grader {

using ChildSettings = std::vector<std::pair<std::string, std::string>>;

// The cache settings every child gets, then the spec's own (`env`).
ChildSettings childSettings(const ChildSpec& spec);

// In a new child, before its work: own process group, dies with the grader, limits, log.
void setUpChild(const Limits& limits, const char* log);

void redirectOutput(const char* log);              // stdout and stderr to `log`
void applySettings(const ChildSettings& settings);  // into this process's environment

// The spec's `run` (an exception counts as exit code 1), then its output flushed.
int runJob(const ChildSpec& spec);

// fork without exec is safe while no thread but the calling one and idle library threads
// (loadBeforeForking) exists.
bool forkIsSafe();

void flushOutput();  // std::cout, std::cerr and every C stream

// Buffered output flushed (else the parent and the child would both write it) and free heap
// pages given back (a child reusing them would copy each on its first write), before a fork.
void prepareFork();

double cpuSecondsOf(const rusage& usage);  // user + sys

}  // namespace sl::grader
