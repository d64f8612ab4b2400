#include "app/heap_huge_pages.hpp"

#include <unistd.h>

#include <cstdlib>
#include <cstring>

namespace ts::app {

std::optional<std::string> tunables_with_huge_pages(const char* current) {
    const std::string have = current ? current : "";
    if (have.find("glibc.malloc.hugetlb=") != std::string::npos) return std::nullopt;
    return have.empty() ? std::string("glibc.malloc.hugetlb=1") : have + ":glibc.malloc.hugetlb=1";
}

void reexec_with_heap_huge_pages(char** argv) {
#if defined(__GLIBC__) && defined(__linux__)
    if (std::getenv("TERRASHADE_NO_HUGE_PAGES")) return;
    const std::optional<std::string> tunables = tunables_with_huge_pages(std::getenv("GLIBC_TUNABLES"));
    if (!tunables || ::setenv("GLIBC_TUNABLES", tunables->c_str(), 1) != 0) return;
    ::execv("/proc/self/exe", argv);
    // exec failed (no /proc): go on as we are, the tunable left set so children do not retry.
#else
    (void)argv;
#endif
}

}  // namespace ts::app
