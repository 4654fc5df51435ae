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

// Re-executes this program with the tunable added when the kernel's transparent huge pages are
// in `madvise` mode and the tunable is not set yet (with `always` they are used anyway, with
// `never` not at all). SHADOWLAB_HUGE_PAGES=0 turns it off. Returns only if nothing was done.
void useHugePages(char** argv);

// One line for `shadowlab info`: "on (...)" or "off (why)".
std::string hugePagesState();

}  // namespace sl::cli
