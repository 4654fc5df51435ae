// huge_pages: see huge_pages.h.
#include "huge_pages.h"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <string>

namespace sl::cli {
namespace {

// The kernel's transparent huge page mode: "always", "madvise", "never" ("" if unknown).
std::string transparentHugePageMode() {
    std::string line;
    std::getline(std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled"), line);
    const auto open = line.find('['), close = line.find(']');
    return open == std::string::npos || close < open ? "" : line.substr(open + 1, close - open - 1);
}

bool turnedOff() {
    const char* off = std::getenv("SHADOWLAB_HUGE_PAGES");
    return off && std::string(off) == "0";
}

// The subcommands that render: one render gains ~0.35 s of CPU (llvmpipe's texture pages);
// the second start costs ~0.03 s since OpenImageIO loads only on first use (image_codec.h).
const char* const kUsers[] = {"render", "view", "grade", "grade-submission", "golden", "study", "truth", "compare", "report", "bench"};

// The subcommand: the first argument that is not an option (nor --backend's value).
std::string subcommand(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--backend") ++i;
        else if (!a.starts_with("-")) return a;
    }
    return "";
}

bool gains(const std::string& command) {
    for (const char* c : kUsers)
        if (command == c) return true;
    return false;
}

std::string tunables() {
    const char* t = std::getenv("GLIBC_TUNABLES");
    return t ? t : "";
}

}  // namespace

void useHugePages(int argc, char** argv) {
    const std::string before = tunables();
    if (!gains(subcommand(argc, argv)) || turnedOff() || before.find("glibc.malloc.hugetlb") != std::string::npos) return;
    if (transparentHugePageMode() != "madvise") return;
    const std::string value = before + (before.empty() ? "" : ":") + "glibc.malloc.hugetlb=1";
    ::setenv("GLIBC_TUNABLES", value.c_str(), 1);
    ::execv("/proc/self/exe", argv);  // returns only on failure: then run as we are
    if (before.empty())
        ::unsetenv("GLIBC_TUNABLES");
    else
        ::setenv("GLIBC_TUNABLES", before.c_str(), 1);
}

std::string hugePagesState() {
    const std::string mode = transparentHugePageMode();
    if (mode == "always") return "on (transparent huge pages: always)";
    if (mode != "madvise") return "off (transparent huge pages: " + (mode.empty() ? "none" : mode) + ")";
    if (tunables().find("glibc.malloc.hugetlb=1") != std::string::npos)
        return "on (glibc.malloc.hugetlb=1, transparent huge pages: madvise)";
    if (turnedOff()) return "off (SHADOWLAB_HUGE_PAGES=0)";
    if (!tunables().empty()) return "off (GLIBC_TUNABLES=" + tunables() + ")";
    return "off for this command (on for render, view, grade, golden, study, truth, compare, report, bench)";
}

}  // namespace sl::cli
