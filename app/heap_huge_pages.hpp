#pragma once
// Transparent huge pages for the heap. A render's arrays (horizons, transfers, the bounce's
// weights) are hundreds of MB touched once each: in 4 KiB pages the first touches were 10-13% of
// `render`'s CPU samples on Grenoble (kernel page-fault work), and with glibc's malloc asked for
// huge pages (its tunable glibc.malloc.hugetlb=1, glibc >= 2.35) the whole command ran in 0.74x
// the wall time (docs/performance.md, "Huge pages"). The tunable is read when the process
// starts, so the executables' main() re-executes itself once with it set.
#include <optional>
#include <string>

namespace ts::app {

// GLIBC_TUNABLES with glibc.malloc.hugetlb=1 added to `current` (null: unset), or nothing when
// `current` already sets glibc.malloc.hugetlb (the user's choice, or this process's own re-exec).
std::optional<std::string> tunables_with_huge_pages(const char* current);

// Re-executes this executable (/proc/self/exe, the same argv) with the tunable set, unless it is
// set already or TERRASHADE_NO_HUGE_PAGES is set; returns (doing nothing) where it cannot.
// Call first in main(), before any thread or output.
void reexec_with_heap_huge_pages(char** argv);

}  // namespace ts::app
