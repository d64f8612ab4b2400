#pragma once
// The period's sun, precomputed once for a DEM (docs/insolation.md): for each latitude band and
// elevation level, one AzimuthTable per period built from the sun's path at a fine step, with
// ESRA's beam and diffuse (esra_clear_sky.hpp). A texel then sums what its horizon lets through
// in each azimuth bin (texel_insolation), at a cost independent of the step.
//
// The sky: ESRA's diffuse horizontal irradiance spread over the sky as the CIE standard clear
// sky (cie_clear_sky.hpp: brighter around the sun and towards the horizon), summed over the
// period once per latitude band (period_sky.hpp) and seen by each texel through its own horizons
// in every horizon azimuth. Reflected: the albedo times an open horizontal plane's global
// irradiation times the part of the texel's cosine-weighted hemisphere that is terrain (1 -
// tilted sky view factor).
#include <array>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "core/solar/azimuth_table.hpp"
#include "core/solar/period_sky.hpp"
#include "core/solar/insolation_period.hpp"
#include "core/solar/sun_path.hpp"
#include "core/util/angles.hpp"
#include "core/visibility/terrain_gather.hpp"

namespace ts {
class ProgressBar;
}

namespace ts::solar {

struct InsolationSettings {
    std::vector<InsolationPeriod> periods;
    std::array<double, 12> linke_monthly{3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3};  // Linke turbidity per month
    double albedo = 0.2;
    double clear_sky_index = 1.0;  // scales beam and diffuse (and so the reflected light)
    double step_minutes = 2.0;     // the sun path's step for the tables
    double clock_longitude_deg = 0;  // the clock of periods, months and days (the DEM's centre)
    double grid_north_deg = 0;       // where true north lies on the DEM's grid (its centre): the sun turns by it
    bool refraction = true;          // the sun's apparent elevation (SPA) hides behind horizons
    int azimuth_bins = 256;
    // The tilted sky view factor and the diffuse sky are integrated over every svf_stride-th bin
    // (the horizon azimuths themselves when the bins subdivide them: their horizons are exact
    // there); the sky in azimuth_bins / svf_stride sectors, halved down to 64 if the bins allow
    // (the summed sky is smooth at that scale).
    int svf_stride = 1;
    // The period's sky is summed for latitude bands this far apart (the nearest serves a texel):
    // it changes with the sun's path far more slowly than the beam's edges do.
    double sky_band_step_deg = 0.5;
    // Texels between two latitude bands take both, linearly (twice the lookups); false: the
    // nearest band (enough when the bands are 0.05 degree apart).
    bool interpolate_bands = false;
    HorizonGrid horizon_grid;
    double sun_radius_rad = 0.004654;
    int threads = 0;
};

// Checks what can be checked before any work (ts::InputError): Linke in (0, 10] (or 0 for a test
// without atmosphere), albedo in [0, 1], clear-sky index in (0, 2], step, bins.
void check_settings(const InsolationSettings& s);

// The quantities of a period, in this order in every output.
enum Quantity { kGlobal = 0, kBeam, kDiffuse, kReflected, kSunHours, kQuantities };
const char* quantity_name(int q);   // "global", "beam", ...
const char* quantity_unit(int q);   // "kWh/m2" or "h"

class InsolationModel {
public:
    // Latitude bands every band_step_deg over [lat_min, lat_max] (nearest band per texel),
    // elevation levels every level_step_m over [z_min, z_max] (linear between two levels).
    InsolationModel(const InsolationSettings& settings, double lat_min_deg, double lat_max_deg, double band_step_deg,
                    double z_min_m, double z_max_m, double level_step_m, ProgressBar* progress = nullptr);

    const InsolationSettings& settings() const { return settings_; }
    int periods() const { return int(settings_.periods.size()); }
    int bands() const { return int(band_lat_.size()); }
    int levels() const { return int(level_z_.size()); }
    double band_latitude(int b) const { return band_lat_[std::size_t(b)]; }
    int band_of(double latitude_deg) const;
    const AzimuthTable& table(int period, int band, int level) const {
        return tables_[(std::size_t(period) * band_lat_.size() + std::size_t(band)) * level_z_.size() + std::size_t(level)];
    }
    // The diffuse sky of a period for a texel of latitude band `band` (the nearest sky band).
    const PeriodSky& sky(int period, int band) const {
        return skies_[std::size_t(period) * std::size_t(sky_bands_) + std::size_t(sky_band_of_[std::size_t(band)])];
    }
    int sky_stride() const { return sky_stride_; }
    std::size_t table_bytes() const;
    std::size_t samples() const { return samples_; }

    // One texel: its horizon angle per azimuth bin (radians, as seen by the tables' bins),
    // normal (ENU, unit), latitude band and height. out[period * kQuantities + q]: kWh/m^2 and h.
    // scratch: at least 2 * azimuth_bins doubles.
    void texel(const float* bin_horizon, const glm::vec3& normal, int band, double z_m, float* out) const;

    // n texels at once, bin by bin (one bin's tables stay in cache across them): horizons_of_bin(j,
    // h) fills h[i] with texel i's horizon in bin j; svf[i] is its tilted sky view factor.
    // out[(i * periods + period) * kQuantities + q].
    struct TexelInfo {
        glm::vec3 normal;
        int band = 0;
        float z = 0;
        float next_band_weight = 0;  // > 0: linear between `band` and band + 1 (band_between)
    };
    // The band at or below a latitude and the weight of the next one, for texels that
    // interpolate between bands (InsolationSettings::interpolate_bands).
    std::pair<int, float> band_between(double latitude_deg) const;
    void run(int n, const TexelInfo* info, const std::function<void(int, float*)>& horizons_of_bin, const float* svf,
             float* out) const;

private:
    InsolationSettings settings_;
    std::vector<double> band_lat_, level_z_;
    double band_first_ = 0, band_step_ = 1;
    std::vector<AzimuthTable> tables_;
    int sky_stride_ = 1;  // bins per sky sector
    int sky_bands_ = 1;
    std::vector<int> sky_band_of_;  // per latitude band
    std::vector<PeriodSky> skies_;  // [period][sky band]
    std::vector<double> cos_phi_, sin_phi_;
    std::size_t samples_ = 0;
};

// The cosine-weighted sky above elevation h in one azimuth (core/visibility/terrain_gather.hpp).
using visibility::sky_above;

// The tilted sky view factor of a receiver with unit normal n under horizons h(phi) given at
// `bins` evenly spaced azimuths (bin j at phi = 2 pi j / bins, each holding over its bin):
// (1/pi) times the integral of max(0, n.w) over the sky above max(h, the receiver's own plane).
// 1 for an open flat texel, (1 + cos slope) / 2 for an open slope.
double tilted_sky_view_factor(const float* bin_horizon, int bins, const glm::dvec3& n, int stride = 1);

}  // namespace ts::solar
