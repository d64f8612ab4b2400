#pragma once
// The quick-look of an insolation map: one band through a colour ramp, with a legend strip
// under it (the ramp, its value range and units, what the band is), as an 8-bit RGB PNG.
#include <string>

namespace ts::app {

// values: width x height, NaN = no data (drawn black). The ramp spans the 1st to 99th
// percentile of the valid values; the legend prints that range and `title` (e.g. "global
// irradiation 2024, kWh/m2"). Writes `path` as it is (callers stage it). Returns the range.
struct QuicklookRange {
    float lo = 0, hi = 0;
};
QuicklookRange write_insolation_quicklook(const std::string& path, int width, int height, const float* values,
                                          const std::string& title, const std::string& unit);

}  // namespace ts::app
