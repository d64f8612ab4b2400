#include "app/options/within_range.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace ts::app {
namespace {

// Shortest form that reads back as the same number: 360, 0.001, 1e-06.
std::string shown(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.15g", v);
    return text;
}

}  // namespace

CLI::Validator within(double lo, double hi) {
    const std::string range = shown(lo) + ".." + shown(hi);
    return CLI::Validator(
        [lo, hi, range](std::string& text) -> std::string {
            errno = 0;
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            // A word that is not a number is the type's error (app/number_flags.hpp), not the range's.
            if (end == text.c_str() || *end != '\0') return {};
            if (errno == ERANGE || !std::isfinite(v) || v < lo || v > hi)
                return "must be within " + range + ", got " + text;
            return {};
        },
        "in " + range, "RANGE");
}

}  // namespace ts::app
