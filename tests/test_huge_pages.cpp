// Huge pages (framework/cli/huge_pages.h): the program re-executes itself with glibc's malloc
// asking for transparent huge pages where the kernel offers them on request (`madvise`), the
// switch SHADOWLAB_HUGE_PAGES=0 turns that off, and the images do not change with it.
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

std::string infoLine(const std::string& env) {
    const auto r = runCommand(env + " " + shadowlabBinary() + " info");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    const auto at = r.output.find("huge pages: ");
    return at == std::string::npos ? "(no huge pages line)\n" + r.output
                                   : r.output.substr(at, r.output.find('\n', at) - at);
}

TEST(HugePages, OnWhereTheKernelOffersThemOnRequest) {
    if (kernelMode().find("[madvise]") == std::string::npos)
        GTEST_SKIP() << "transparent huge pages not in madvise mode here: " << kernelMode();
    // The re-executed process sees the tunable, so info reports it as on.
    EXPECT_EQ(infoLine("env -u GLIBC_TUNABLES"),
              "huge pages: on (glibc.malloc.hugetlb=1, transparent huge pages: madvise)");
    EXPECT_EQ(infoLine("env -u GLIBC_TUNABLES SHADOWLAB_HUGE_PAGES=0"),
              "huge pages: off (SHADOWLAB_HUGE_PAGES=0)");
    // A user's own tunables are kept and not overridden.
    EXPECT_EQ(infoLine("GLIBC_TUNABLES=glibc.malloc.hugetlb=0"),
              "huge pages: off (GLIBC_TUNABLES=glibc.malloc.hugetlb=0)");
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
    const auto off = render("SHADOWLAB_HUGE_PAGES=0", "off");
    ASSERT_FALSE(on.empty());
    EXPECT_EQ(on, off);
}

}  // namespace
}  // namespace sl::test
