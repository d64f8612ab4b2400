#include "core/util/memory.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

namespace ts {

namespace {

constexpr std::uint64_t kUnknown = std::numeric_limits<std::uint64_t>::max();

std::uint64_t g_cap = 0;

// MemAvailable in bytes, kUnknown if /proc/meminfo is missing or lacks it (kernels < 3.14).
std::uint64_t mem_available() {
    std::ifstream in("/proc/meminfo");
    std::string key;
    std::uint64_t kib = 0;
    std::string unit;
    while (in >> key >> kib) {
        std::getline(in, unit);
        if (key == "MemAvailable:") return kib * 1024;
    }
    return kUnknown;
}

// A cgroup's limit, kUnknown when unlimited ("max", or v1's huge sentinel) or unreadable.
std::uint64_t cgroup_limit() {
    for (const char* path : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
        std::ifstream in(path);
        std::string text;
        if (!(in >> text) || text == "max") continue;
        std::uint64_t v = 0;
        std::istringstream parse(text);
        if (!(parse >> v) || v >= (std::uint64_t(1) << 62)) continue;
        return v;
    }
    return kUnknown;
}

}  // namespace

std::uint64_t available_memory() {
    std::uint64_t v = std::min(mem_available(), cgroup_limit());
    if (g_cap) v = std::min(v, g_cap);
    return v;
}

void set_memory_cap(std::uint64_t bytes) { g_cap = bytes; }

std::uint64_t memory_cap() { return g_cap; }

std::string format_bytes(std::uint64_t bytes) {
    char buffer[64];
    if (bytes >= 1000ull * 1000 * 1000) {
        std::snprintf(buffer, sizeof buffer, "%.1f GB", double(bytes) / 1e9);
    } else if (bytes >= 1000ull * 1000) {
        std::snprintf(buffer, sizeof buffer, bytes < 100'000'000 ? "%.1f MB" : "%.0f MB", double(bytes) / 1e6);
    } else if (bytes >= 1000) {
        std::snprintf(buffer, sizeof buffer, "%.0f KB", double(bytes) / 1e3);
    } else {
        std::snprintf(buffer, sizeof buffer, "%llu bytes", static_cast<unsigned long long>(bytes));
    }
    return buffer;
}

}  // namespace ts
