// The fast integral against the brute-force reference on a real DEM: a crop of the Grenoble
// Copernicus DSM (French Alps, 50 x 50 texels of ~160 x 220 m), monthly periods over a year,
// 16 texels spread over the crop. Reference: every minute, the sun's visibility from the
// horizon in the sun's own azimuth (linear between the horizon azimuths), ESRA at the texel's
// own height and latitude, the diffuse sky integrated over the sky above the horizons every
// 30 minutes (ReferenceSky: the sky changes slowly; every minute would take minutes).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/dem/crop.hpp"
#include "core/dem/fill_voids.hpp"
#include "core/dem/read_dem.hpp"
#include "core/solar/insolation_map.hpp"
#include "core/solar/insolation_reference.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/visibility/compute_horizons.hpp"

namespace ts::solar {
namespace {

struct Errors {
    double year = 0, month = 0, hours_per_day = 0;  // worst |fast / reference - 1|, worst |diff| / days
};

// Built once for the suite: the crop, its horizons, the fast map.
struct GrenobleCase {
    GrenobleCase() {
        dem_ = dem::crop(dem::read_dem(std::string(TS_SOURCE_DIR) + "/data/grenoble_500px.tif"),
                         {5.70, 45.15, 5.80, 45.25});
        dem::fill_voids(dem_);
        grid_ = terrain::metric_view(dem_);
        visibility::HorizonOptions ho;
        ho.directions = 64;
        horizons_ = visibility::compute_horizons(grid_, ho);
        normals_ = render::terrain_normals(grid_);
        lat_ = texel_latitudes(dem_.georef, 0);
        settings_.clock_longitude_deg = 5.75;
        settings_.periods = make_periods({2023, 1, 1}, {2023, 12, 31}, PeriodSplit::month, 5.75);
        settings_.linke_monthly = {2.5, 2.7, 3.0, 3.3, 3.5, 3.6, 3.6, 3.5, 3.2, 2.9, 2.6, 2.5};
        settings_.step_minutes = 1.0;
        settings_.azimuth_bins = 4 * ho.directions;
        settings_.svf_stride = 4;
        float zmin = 1e9f, zmax = -1e9f;
        for (float z : dem_.z) zmin = std::min(zmin, z), zmax = std::max(zmax, z);
        const InsolationModel model(settings_, 45.15, 45.25, 0.05, zmin, zmax, 500.0);
        map_ = integrate_insolation(model, grid_, horizons_, normals_, lat_);
        path_ = sample_sun_path(settings_.periods, settings_.step_minutes, settings_.clock_longitude_deg);
    }

    std::size_t texel(int k, int& c, int& r) const {
        c = 3 + (k % 4) * (grid_.width - 6) / 3, r = 3 + (k / 4) * (grid_.height - 6) / 3;
        return std::size_t(r) * grid_.width + c;
    }

    // The fast map against the reference of texel k under the horizons `h` (D azimuths).
    void compare(int k, const visibility::HorizonSet& h, Errors& e) const {
        int c = 0, r = 0;
        const std::size_t t = texel(k, c, r);
        std::vector<float> azimuths(static_cast<std::size_t>(h.directions));
        for (int d = 0; d < h.directions; ++d) azimuths[std::size_t(d)] = h.at(d, c, r);
        const glm::dvec3 n(normals_.x[t], normals_.y[t], normals_.z[t]);
        ReferenceSky sky;
        sky.stride = 30;
        sky.azimuths = std::min(h.directions, 90);
        sky.elevations = 16;
        const std::vector<double> ref = reference_insolation(settings_, path_, lat_[t], grid_.z[t], n, azimuths, sky);
        double year_fast = 0, year_ref = 0;
        for (int p = 0; p < 12; ++p) {
            const double f = map_.band(p, kGlobal)[t], g = ref[std::size_t(p) * kQuantities + kGlobal];
            year_fast += f, year_ref += g;
            e.month = std::max(e.month, std::abs(f / g - 1));
            const auto& period = settings_.periods[std::size_t(p)];
            const double days = std::chrono::duration<double, std::ratio<86400>>(period.end - period.begin).count();
            const double hours = map_.band(p, kSunHours)[t] - ref[std::size_t(p) * kQuantities + kSunHours];
            e.hours_per_day = std::max(e.hours_per_day, std::abs(hours) / days);
        }
        e.year = std::max(e.year, std::abs(year_fast / year_ref - 1));
    }

    dem::Dem dem_;
    terrain::HeightGrid grid_;
    visibility::HorizonSet horizons_;
    render::NormalField normals_;
    std::vector<float> lat_;
    InsolationSettings settings_;
    InsolationMap map_;
    std::vector<EphemerisSample> path_;
};

class InsolationDem : public ::testing::Test {
protected:
    static const GrenobleCase& data() {
        static const GrenobleCase instance;
        return instance;
    }
};

// Same horizons (64 azimuths) on both sides: what the tables and azimuth bins cost.
TEST_F(InsolationDem, TablesMatchTheMinuteByMinuteSumWithTheSameHorizons) {
    Errors e;
    for (int k = 0; k < 16; ++k) data().compare(k, data().horizons_, e);
    std::printf("fast vs minute-by-minute, same horizons: annual global %.3f%%, monthly %.3f%%, sun %.2f min/day\n",
                100 * e.year, 100 * e.month, 60 * e.hours_per_day);
    EXPECT_LT(e.year, 0.005);
    EXPECT_LT(e.month, 0.01);
    EXPECT_LT(e.hours_per_day, 5.0 / 60.0);
}

// The reference with horizons in 720 azimuths: the horizon's own azimuth resolution. The annual
// global holds within 0.5%; a month of a texel whose winter sun grazes a ridge differs more
// (docs/insolation.md, "Accuracy"), so only the year is checked here.
TEST_F(InsolationDem, AnnualGlobalMatchesTheSumUnderFineHorizons) {
    visibility::HorizonOptions ho;
    ho.directions = 720;
    const visibility::HorizonSet fine = visibility::compute_horizons(data().grid_, ho);
    Errors e;
    for (int k = 0; k < 16; k += 2) data().compare(k, fine, e);
    std::printf("fast (64 azimuths) vs minute-by-minute (720): annual global %.3f%%, monthly %.3f%%, sun %.2f min/day\n",
                100 * e.year, 100 * e.month, 60 * e.hours_per_day);
    EXPECT_LT(e.year, 0.005);
}

}  // namespace
}  // namespace ts::solar
