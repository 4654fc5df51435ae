// study_cost: the study's cost axis. A pass's cost is the CPU time of every thread of the
// process around its glFinish (cost_clock.h; or callgrind's instruction count, the exact mode): llvmpipe's threads do the work, and time spent
// waiting for a core another process holds is not counted, so the figure holds on a busy
// machine where wall time does not. The copy pass (1024² RGBA32F) is measured the same way,
// interleaved with the row's frames (copy, frame, copy, frame, ...), so that a slow drift
// touches both alike; its ratio travels between machines. Statistics: minimum (the headline:
// interference only ever adds), median and maximum over the repeats.
#pragma once

#include "gpu_resources.h"
#include "renderer.h"

#include <string>
#include <vector>

namespace sl {

struct CostStats {
    double min = 0, median = 0, max = 0;
};
CostStats costStats(const std::vector<double>& values);

// The copy pass, for the ratio: one measurement per call (cost_clock.h's unit).
class CopyYardstick {
public:
    explicit CopyYardstick(Renderer& renderer);
    double measureOnce();

private:
    Renderer& renderer_;
    Texture src_, dst_;
};

}  // namespace sl
