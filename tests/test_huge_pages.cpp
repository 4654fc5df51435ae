// Huge pages (cli/huge_pages.h): the commands that render re-execute themselves with
// glibc's malloc asking for transparent huge pages where the kernel offers them on request
// (`madvise`), the switch SHADOWLAB_HUGE_PAGES=0 turns that off, a query does not re-execute,
// and the images do not change with huge pages.
#include "gl_test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace sl::test {
namespace {

std::string kernelMode() {
    std::string line;
    std::getline(std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled"), line);
    return line;
}

// The "huge pages: ..." line of a command's output.
std::string hugePagesLine(const std::string& env, const std::string& args) {
    const auto r = runCommand(env + " " + shadowlabBinary() + " " + args);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    const auto at = r.output.find("huge pages: ");
    return at == std::string::npos ? "(no huge pages line)\n" + r.output
                                   : r.output.substr(at, r.output.find('\n', at) - at);
}

TEST(HugePages, OnForTheCommandsThatRender) {
    if (kernelMode().find("[madvise]") == std::string::npos)
        GTEST_SKIP() << "transparent huge pages not in madvise mode here: " << kernelMode();
    const std::string bench = "bench --size 16 --repeats 3 --lighting-scene none";
    // The re-executed process sees the tunable, so the bench reports it as on.
    EXPECT_EQ(hugePagesLine("env -u GLIBC_TUNABLES", bench),
              "huge pages: on (glibc.malloc.hugetlb=1, transparent huge pages: madvise)");
    EXPECT_EQ(hugePagesLine("env -u GLIBC_TUNABLES SHADOWLAB_HUGE_PAGES=0", bench),
              "huge pages: off (SHADOWLAB_HUGE_PAGES=0)");
    // A user's own tunables are kept and not overridden.
    EXPECT_EQ(hugePagesLine("GLIBC_TUNABLES=glibc.malloc.hugetlb=0", bench),
              "huge pages: off (GLIBC_TUNABLES=glibc.malloc.hugetlb=0)");
    // A query does not pay for a second start.
    EXPECT_EQ(hugePagesLine("env -u GLIBC_TUNABLES", "--backend auto info"),
              "huge pages: off for this command (on for render, view, grade, golden, study, "
              "truth, compare, report, bench)");
}

TEST(HugePages, ImagesAreTheSameBytesWithAndWithout) {
    const fs::path dir = tempDir("huge_pages");
    auto render = [&](const std::string& env, const std::string& name) {
        const auto r = runCommand(env + " " + shadowlabBinary() + " render --scene " +
                                  scenePath("contact").string() + " --out " + (dir / name).string());
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return nlohmann::json::parse(std::ifstream(dir / name / "render.json"))["sha256"];
    };
    const auto on = render("env -u GLIBC_TUNABLES", "on");
    const auto off = render("env -u GLIBC_TUNABLES SHADOWLAB_HUGE_PAGES=0", "off");
    ASSERT_FALSE(on.empty());
    EXPECT_EQ(on, off);
}

}  // namespace
}  // namespace sl::test
