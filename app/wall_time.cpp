#include "app/wall_time.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string_view>

#include "core/util/error.hpp"

namespace ts::app {
namespace {

bool parse_number(std::string_view s, double& out) {
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return !s.empty() && ec == std::errc() && p == s.data() + s.size() && out >= 0;
}

bool parse_clock(std::string_view s, double& out) {
    // [D-]HH:MM:SS or MM:SS
    double days = 0;
    if (const auto dash = s.find('-'); dash != std::string_view::npos) {
        if (!parse_number(s.substr(0, dash), days)) return false;
        s = s.substr(dash + 1);
    }
    double parts[3] = {0, 0, 0};
    int n = 0;
    while (!s.empty()) {
        if (n == 3) return false;
        const auto colon = s.find(':');
        if (!parse_number(s.substr(0, colon), parts[n++])) return false;
        s = colon == std::string_view::npos ? std::string_view() : s.substr(colon + 1);
    }
    if (n < 2) return false;
    out = days * 86400 + (n == 3 ? parts[0] * 3600 + parts[1] * 60 + parts[2] : parts[0] * 60 + parts[1]);
    return true;
}

bool parse_units(std::string_view s, double& out) {
    out = 0;
    bool any = false;
    while (!s.empty()) {
        const auto unit = s.find_first_of("dhms");
        if (unit == std::string_view::npos) return false;
        double v = 0;
        if (!parse_number(s.substr(0, unit), v)) return false;
        const char u = s[unit];
        out += v * (u == 'd' ? 86400 : u == 'h' ? 3600 : u == 'm' ? 60 : 1);
        any = true;
        s = s.substr(unit + 1);
    }
    return any;
}

}  // namespace

double parse_wall_time(const std::string& text) {
    double s = 0;
    const bool ok = text.find(':') != std::string::npos ? parse_clock(text, s) : parse_units(text, s);
    if (!ok || !(s > 0) || !std::isfinite(s))
        throw InputError("--wall-time " + text + ": give e.g. 2h, 1h30m, 45m, 90s or HH:MM:SS");
    return s;
}

std::string format_duration(double s) {
    char buf[64];
    if (s < 120) std::snprintf(buf, sizeof buf, "%.1f s", s);
    else if (s < 7200) std::snprintf(buf, sizeof buf, "%.1f min", s / 60);
    else std::snprintf(buf, sizeof buf, "%.1f h", s / 3600);
    return buf;
}

std::string format_bytes(double b) {
    const char* units[] = {"B", "KB", "MB", "GB", "TB", "PB"};
    int u = 0;
    while (b >= 1000 && u < 5) b /= 1000, ++u;
    char buf[64];
    std::snprintf(buf, sizeof buf, u == 0 ? "%.0f %s" : "%.1f %s", b, units[u]);
    return buf;
}

std::string slurm_time(double seconds) {
    const auto minutes = std::int64_t(std::ceil(seconds / 60 - 1e-9));
    const std::int64_t days = minutes / 1440, hours = minutes / 60 % 24, mins = minutes % 60;
    char buf[64];
    if (days > 0) std::snprintf(buf, sizeof buf, "%lld-%02lld:%02lld:00", static_cast<long long>(days),
                                static_cast<long long>(hours), static_cast<long long>(mins));
    else std::snprintf(buf, sizeof buf, "%lld:%02lld:00", static_cast<long long>(hours), static_cast<long long>(mins));
    return buf;
}

std::int64_t shards_for_wall_time(double work_s, double fixed_s, double wall_s) {
    if (fixed_s >= wall_s) return 0;
    return std::max<std::int64_t>(1, std::int64_t(std::ceil(work_s / (wall_s - fixed_s) - 1e-9)));
}

}  // namespace ts::app
