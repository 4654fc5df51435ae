// huge_pages: run the program with glibc's malloc asking the kernel for transparent huge pages.
//
// llvmpipe keeps every texture in malloc()ed memory, and each fresh 4 KiB page costs a page
// fault (a VM exit under KVM): a grade touched 1.8 million pages, half of its CPU time in the
// kernel. With GLIBC_TUNABLES=glibc.malloc.hugetlb=1 (glibc >= 2.35) malloc marks its large
// blocks MADV_HUGEPAGE, and 2 MiB pages cut the faults 6x (docs/performance.md, "Grading time").
// A tunable is read when a process starts, so the program re-executes itself once with it.
#pragma once

#include <string>

namespace sl::cli {

// Re-executes this program with the tunable added when the subcommand renders (render, view,
// grade, golden, study, truth, compare, report, bench), the kernel's transparent huge pages are
// in `madvise` mode (with `always` they are used anyway, with `never` not at all) and the
// tunable is not set yet. The second start costs ~0.03 s (OpenImageIO's libraries load only
// later, on first use: render/image_codec.h); one render saves ~0.35 s of CPU. Queries (info,
// probe, --help) do not re-execute. SHADOWLAB_HUGE_PAGES=0 turns it off. Returns only if
// nothing was done.
void useHugePages(int argc, char** argv);

// One line for `shadowlab info` and the bench's header: "on (...)" or "off (why)".
std::string hugePagesState();

}  // namespace sl::cli
