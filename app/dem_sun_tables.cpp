#include "app/dem_sun_tables.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/util/error.hpp"
#include "core/util/progress_bar.hpp"
#include "core/util/stopwatch.hpp"

namespace ts::app {

DemSunTables build_dem_sun_tables(const dem::Dem& dem, solar::InsolationSettings settings,
                                  const solar::CalendarDate& first, const solar::CalendarDate& last,
                                  solar::PeriodSplit split, double band_step_deg, double level_step_m) {
    // The clock of days and months: mean solar time at the DEM's centre.
    const glm::dvec2 centre = dem.georef.pixel_to_lonlat(dem.width * 0.5, dem.height * 0.5);
    if (!std::isfinite(centre.x) || !std::isfinite(centre.y))
        throw InputError(dem.source + ": its CRS gives no longitude and latitude");
    settings.clock_longitude_deg = centre.x;
    settings.grid_north_deg = dem.georef.grid_azimuth_of_north_deg();
    settings.periods = solar::make_periods(first, last, split, centre.x);

    DemSunTables out;
    out.latitude = solar::texel_latitudes(dem.georef, settings.threads);
    float lat_min = 90, lat_max = -90, z_min = 1e30f, z_max = -1e30f;
    for (std::size_t i = 0; i < out.latitude.size(); ++i) {
        lat_min = std::min(lat_min, out.latitude[i]), lat_max = std::max(lat_max, out.latitude[i]);
        if (std::isfinite(dem.z[i])) z_min = std::min(z_min, dem.z[i]), z_max = std::max(z_max, dem.z[i]);
    }
    if (!(z_max >= z_min)) z_min = z_max = 0;

    const Stopwatch watch;
    // The tables hold a few MB per latitude band and elevation level (a year: ~2.5 MB at 256
    // bins); a DEM spanning many degrees or kilometres gets coarser bands and levels, said.
    constexpr int kMaxLevels = 8, kMaxTableGroups = 160;
    double level_step = level_step_m, band_step = band_step_deg;
    if ((z_max - z_min) / level_step > kMaxLevels - 1) level_step = (z_max - z_min) / (kMaxLevels - 1);
    const int n_levels = (z_max - z_min) > 1e-9 ? int(std::ceil((z_max - z_min) / level_step - 1e-9)) + 1 : 1;
    const int max_bands = std::max(1, kMaxTableGroups / n_levels);
    if ((lat_max - lat_min) / band_step > max_bands - 1) {
        band_step = (lat_max - lat_min) / (max_bands - 1);
        settings.interpolate_bands = true;
        std::fprintf(stderr,
                     "terrashade: note: the DEM spans %.3g degrees of latitude: sun tables every %.3g degrees (%d bands, "
                     "each texel linear between two) and %d elevation levels, to keep them in memory\n",
                     double(lat_max - lat_min), band_step, max_bands, n_levels);
    }
    const int n_bands = int(std::ceil((lat_max - lat_min) / band_step - 1e-9)) + 1;
    ProgressBar bar("sun tables", std::uint64_t(std::max(1, n_bands)), "latitude bands");
    out.model = std::make_shared<const solar::InsolationModel>(settings, lat_min, lat_max, band_step, z_min, z_max,
                                                               level_step, &bar);
    bar.finish();
    out.seconds = watch.seconds();
    out.settings = settings;
    return out;
}

}  // namespace ts::app
