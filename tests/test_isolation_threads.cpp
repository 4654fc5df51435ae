// The grader forks its workers without exec only while no thread could hold a lock a worker
// needs (grader/intake/isolation.h). Loading the image codec starts log4cplus's idle pool; loaded
// through loadBeforeForking, those threads count as idle and workers are still forked.
#include "gl_test_support.h"
#include "image_codec.h"
#include "isolation.h"

#include <gtest/gtest.h>

#include <fstream>

namespace sl::test {
namespace {

size_t threadCount() {
    size_t n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator("/proc/self/task")) ++n;
    return n;
}

TEST(IsolationThreads, WorkersAreForkedAfterTheCodecLoads) {
    const size_t before = threadCount();
    grader::loadBeforeForking([] { imageCodec(); });
    // Why the grader needs loadBeforeForking at all (if this stops holding, it is harmless).
    std::cout << "threads started by loading the codec: " << threadCount() - before << "\n";
    const fs::path dir = tempDir("isolation_threads");
    grader::ChildSpec spec;
    spec.logPath = dir / "log.txt";
    // Forked: `run` writes the marker. Exec'd: this test binary runs with a filter that matches
    // no test, and writes nothing.
    spec.run = [dir] {
        std::ofstream(dir / "forked") << "yes\n";
        return 0;
    };
    spec.args = {"--gtest_filter=NoTestHasThisName"};
    const auto results = grader::runChildren({spec}, {20.0, 4096}, 1);
    ASSERT_EQ(results.size(), 1u);
    EXPECT_EQ(results[0].kind, grader::ChildResult::Exited);
    EXPECT_EQ(results[0].exitCode, 0) << results[0].log;
    EXPECT_TRUE(fs::exists(dir / "forked")) << "the worker was exec'd, not forked";
}

}  // namespace
}  // namespace sl::test
