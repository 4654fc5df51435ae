// The cost clock (cost_clock.h, its default "cpu" clock) counts llvmpipe's threads: a compute pass runs on llvmpipe's own thread pool
// while the caller waits in glFinish, so a clock of the calling thread alone (or a pool that
// never started) would make every pass look free. Not a timing test: it checks what is counted.
#include "cost_clock.h"
#include "gl_api.h"
#include "gl_test_support.h"
#include "renderer.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <ctime>

namespace sl {
namespace {

double threadCpuMillis() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

TEST(CostClock, APassIsCountedOnLlvmpipesThreadsNotTheCallers) {
    const char* threads = std::getenv("LP_NUM_THREADS");
    if (threads && std::atoi(threads) == 0)
        GTEST_SKIP() << "LP_NUM_THREADS=0: llvmpipe runs every pass on the calling thread";
    test::sharedContext();
    Renderer r(test::library(defaultSolution()));  // the copy pass is the framework's
    Texture src = Texture::create(2048, 2048, GL_RGBA32F), dst = Texture::create(2048, 2048, GL_RGBA32F);
    r.copyPass(src, dst);  // compile
    gl::Finish();
    const double process0 = processCpuMillis(), thread0 = threadCpuMillis();
    for (int i = 0; i < 4; ++i) r.copyPass(src, dst);
    gl::Finish();
    const double process = processCpuMillis() - process0, thread = threadCpuMillis() - thread0;
    EXPECT_GT(process, 5.0) << "four 2048² copies cost no CPU time";
    EXPECT_GT(process, 3.0 * thread)
        << "the passes' CPU time is mostly the calling thread's (" << thread << " of " << process
        << " ms): llvmpipe's pool did not run them, or the clock misses its threads";
    EXPECT_NE(costMethod().find("CPU ms"), std::string::npos) << costMethod();
    EXPECT_NE(costMethod().find("LP_NUM_THREADS="), std::string::npos) << costMethod();
}

}  // namespace
}  // namespace sl
