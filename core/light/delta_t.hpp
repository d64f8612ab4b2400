#pragma once
// Delta T = TT - UT1, the clock difference the SPA needs to place the Earth on its orbit
// (the Earth's rotation uses UT, the orbit uses Terrestrial Time).
#include "core/light/utc_time.hpp"

namespace ts::light {

// Espenak & Meeus (NASA "Five Millennium Canon of Solar Eclipses", 2006) polynomial fits, in
// seconds, for a decimal year. Observed values are within about 1 s of them for 1900-2005;
// for 2024 the fit gives 73.9 s against about 69.2 s observed (IERS). Delta T only moves the
// Earth along its orbit (0.9856 deg/day), so a 5 s error shifts the sun by 0.00006 deg: below
// the SPA's own +-0.0003 deg uncertainty. Pass a measured value to reproduce other tools exactly.
double espenak_meeus_delta_t(double decimal_year);

// The model at an instant (its decimal year).
double default_delta_t(UtcTime t);

}  // namespace ts::light
