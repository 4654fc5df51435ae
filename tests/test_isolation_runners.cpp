// One submission's children may run one after another in a runner (Limits::reuseProcesses).
// What a runner must not change: each child's exit code, log and limit are its own, a crash or
// a hang costs the child it hit and no other, a child's settings never leak into another's, and
// a call with two runners ends (each runner sees the end of its own job pipe).
#include "gl_test_support.h"
#include "isolation.h"

#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <fstream>
#include <thread>
#include <unistd.h>

namespace sl::test {
namespace {

using grader::ChildResult;
using grader::ChildSpec;

// A child that prints its pid and the value of SL_RUNNER_PROBE, then does `then`.
ChildSpec probeChild(const fs::path& log, std::function<int()> then) {
    ChildSpec spec;
    spec.logPath = log;
    spec.args = {"--gtest_filter=NoTestHasThisName"};  // exec'd: prints no pid line
    spec.run = [then] {
        const char* v = std::getenv("SL_RUNNER_PROBE");
        std::cout << "pid " << ::getpid() << " probe " << (v ? v : "unset") << std::endl;  // flushed: a crash loses a buffer
        return then();
    };
    return spec;
}

std::string pidOf(const ChildResult& r) {
    const auto at = r.log.find("pid ");
    if (at == std::string::npos) return "";
    return r.log.substr(at + 4, r.log.find(' ', at + 4) - at - 4);
}

TEST(IsolationRunners, ACrashOrAHangCostsOnlyItsChildAndTheOthersKeepTheirResults) {
    const fs::path dir = tempDir("isolation_runners");
    std::vector<ChildSpec> specs;
    specs.push_back(probeChild(dir / "0.log", [] { return 3; }));
    specs.push_back(probeChild(dir / "1.log", [] { return 0; }));
    specs.push_back(probeChild(dir / "2.log", [] {
        std::raise(SIGSEGV);
        return 0;
    }));
    specs.push_back(probeChild(dir / "3.log", [] { return 5; }));
    specs.push_back(probeChild(dir / "4.log", [] {
        for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
        return 0;
    }));
    specs[4].timeoutSeconds = 1.0;
    specs.push_back(probeChild(dir / "5.log", [] { return 0; }));
    const auto results = grader::runChildren(specs, {20.0, 4096, true}, 1);
    ASSERT_EQ(results.size(), specs.size());
    EXPECT_EQ(results[0].kind, ChildResult::Exited);
    EXPECT_EQ(results[0].exitCode, 3) << results[0].log;
    EXPECT_EQ(results[1].exitCode, 0) << results[1].log;
    EXPECT_EQ(results[2].kind, ChildResult::Signalled) << results[2].log;
    EXPECT_EQ(results[2].signal, SIGSEGV);
    EXPECT_EQ(results[3].kind, ChildResult::Exited);
    EXPECT_EQ(results[3].exitCode, 5) << results[3].log;
    EXPECT_EQ(results[4].kind, ChildResult::TimedOut);
    EXPECT_EQ(results[5].kind, ChildResult::Exited);
    EXPECT_EQ(results[5].exitCode, 0) << results[5].log;
    // Each log holds its own child's line only.
    for (size_t i = 0; i < results.size(); ++i) {
        EXPECT_EQ(std::count(results[i].log.begin(), results[i].log.end(), '\n'), 1) << i << ": " << results[i].log;
        EXPECT_FALSE(pidOf(results[i]).empty()) << "child " << i << " was exec'd, not run: " << results[i].log;
    }
    // Reused until something kills it: 0, 1 and 2 in one runner, 3 and 4 in the next, 5 in a third.
    EXPECT_EQ(pidOf(results[0]), pidOf(results[1]));
    EXPECT_EQ(pidOf(results[1]), pidOf(results[2]));
    EXPECT_NE(pidOf(results[2]), pidOf(results[3]));
    EXPECT_EQ(pidOf(results[3]), pidOf(results[4]));
    EXPECT_NE(pidOf(results[4]), pidOf(results[5]));
}

TEST(IsolationRunners, AChildsSettingsNeverReachAnotherAndTwoRunnersEnd) {
    const fs::path dir = tempDir("isolation_runner_settings");
    std::vector<ChildSpec> specs;
    for (int i = 0; i < 8; ++i) {
        specs.push_back(probeChild(dir / (std::to_string(i) + ".log"), [] { return 0; }));
        if (i % 3 == 1) specs.back().env = {{"SL_RUNNER_PROBE", "set" + std::to_string(i)}};
    }
    const auto results = grader::runChildren(specs, {20.0, 4096, true}, 2);
    ASSERT_EQ(results.size(), specs.size());
    for (size_t i = 0; i < results.size(); ++i) {
        EXPECT_EQ(results[i].exitCode, 0) << results[i].log;
        const std::string want = i % 3 == 1 ? "probe set" + std::to_string(i) : "probe unset";
        EXPECT_NE(results[i].log.find(want), std::string::npos) << i << ": " << results[i].log;
    }
    // Two at a time, and still fewer processes than children.
    std::set<std::string> pids;
    for (const auto& r : results) pids.insert(pidOf(r));
    EXPECT_LT(pids.size(), specs.size());
}

TEST(IsolationRunners, TurnedOffEveryChildIsAProcessOfItsOwn) {
    const fs::path dir = tempDir("isolation_runners_off");
    std::vector<ChildSpec> specs;
    for (int i = 0; i < 3; ++i) specs.push_back(probeChild(dir / (std::to_string(i) + ".log"), [] { return 0; }));
    ::setenv("SHADOWLAB_GRADER_RUNNERS", "0", 1);
    const auto results = grader::runChildren(specs, {20.0, 4096, true}, 1);
    ::unsetenv("SHADOWLAB_GRADER_RUNNERS");
    std::set<std::string> pids;
    for (const auto& r : results) pids.insert(pidOf(r));
    EXPECT_EQ(pids.size(), specs.size());
}

}  // namespace
}  // namespace sl::test
