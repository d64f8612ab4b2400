#pragma once
// One number as a CSV cell for the bench commands' --csv output: 6 significant digits, and an
// empty cell for NaN (a measurement that does not apply), which the chart scripts read as missing.
#include <cmath>
#include <cstdio>
#include <string>

namespace ts::app {

inline std::string csv_number(double v) {
    if (std::isnan(v)) return "";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

}  // namespace ts::app
