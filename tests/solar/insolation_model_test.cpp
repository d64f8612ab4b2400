// The fast sums against closed forms and independent step-by-step integrals (docs/insolation.md,
// "Accuracy").
#include "core/solar/insolation_model.hpp"

#include <chrono>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/light/sun_position.hpp"
#include "core/solar/esra_clear_sky.hpp"
#include "core/solar/insolation_map.hpp"
#include "core/solar/insolation_reference.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/util/angles.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/sun_visibility.hpp"

namespace ts::solar {
namespace {

InsolationSettings day_settings(CalendarDate day, double linke, double step_minutes, bool refraction) {
    InsolationSettings s;
    s.periods = make_periods(day, day, PeriodSplit::day, 0.0);
    s.linke_monthly.fill(linke);
    s.step_minutes = step_minutes;
    s.refraction = refraction;
    s.threads = 1;
    return s;
}

// One texel of a model built for one latitude and height, under a constant horizon.
std::vector<float> texel_of(const InsolationSettings& s, double lat, double z, glm::vec3 n, float horizon = -0.1f) {
    const InsolationModel model(s, lat, lat, 0.1, z, z, 500.0);
    std::vector<float> h(std::size_t(s.azimuth_bins), horizon), out(s.periods.size() * kQuantities);
    model.texel(h.data(), n, 0, z, out.data());
    return out;
}

// The daily extraterrestrial irradiation of a horizontal plane (Wh/m^2), the closed form with
// the declination at noon: (24/pi) G0 (ws sin(lat) sin(d) + cos(lat) cos(d) sin(ws)).
double daily_h0(double lat_deg, CalendarDate day, int day_of_year) {
    light::SunPositionInput in;
    in.time = local_midnight(day, 0.0) + std::chrono::hours(12);
    const double d = radians(light::sun_position(in).declination_deg);
    const double lat = radians(lat_deg);
    const double ws = std::acos(std::clamp(-std::tan(lat) * std::tan(d), -1.0, 1.0));
    return 24.0 / kPi * extraterrestrial_normal_irradiance(day_of_year) *
           (ws * std::sin(lat) * std::sin(d) + std::cos(lat) * std::cos(d) * std::sin(ws));
}

// Beam on a plane of normal n summed minute by minute straight from the SPA (no refraction),
// the plane hiding the sun behind it: an integral independent of the tables (kWh/m^2).
double spa_beam(CalendarDate first, int days, double lat, double linke, glm::dvec3 n, double step_min) {
    double sum = 0;
    const auto begin = local_midnight(first, 0.0);
    const int steps = int(std::lround(days * 1440.0 / step_min));
    for (int i = 0; i < steps; ++i) {
        light::SunPositionInput in;
        in.time = begin + std::chrono::microseconds(std::int64_t((i + 0.5) * step_min * 60e6));
        in.observer.latitude_deg = lat;
        in.atmosphere.pressure_hpa = 0;
        const light::SunPosition p = light::sun_position(in);
        if (p.elevation_deg <= 0) continue;
        const glm::dvec3 s = light::sun_direction_enu(p);
        const double doy = local_day(in.time, 0.0).day_of_year;
        const double b = beam_normal_irradiance(extraterrestrial_normal_irradiance(doy), linke,
                                                radians(p.elevation_deg), 0.0);
        sum += b * std::max(0.0, glm::dot(n, s)) * step_min / 60.0;
    }
    return sum / 1000.0;
}

TEST(InsolationModel, FlatPlaneWithoutAtmosphereGivesTheClosedFormDailyIrradiation) {
    struct Case {
        double lat;
        CalendarDate day;
        int doy;
    };
    for (const Case c : {Case{0, {2024, 3, 20}, 80}, Case{45, {2024, 3, 20}, 80}, Case{45, {2024, 6, 21}, 173},
                         Case{70, {2024, 3, 20}, 80}, Case{70, {2024, 6, 21}, 173}, Case{-45, {2024, 12, 21}, 356}}) {
        const auto s = day_settings(c.day, 0.0, 1.0, false);
        const auto out = texel_of(s, c.lat, 0.0, {0, 0, 1});
        const double h0 = daily_h0(c.lat, c.day, c.doy) / 1000.0;
        EXPECT_NEAR(out[kBeam] / h0, 1.0, 2e-3) << "latitude " << c.lat << ", day " << c.doy;
    }
}

TEST(InsolationModel, FlatPlaneEsraBeamMatchesAMinuteByMinuteSpaIntegral) {
    for (double lat : {0.0, 45.0, 70.0}) {
        const auto s = day_settings({2024, 5, 10}, 3.0, 2.0, false);
        const auto out = texel_of(s, lat, 0.0, {0, 0, 1});
        const double ref = spa_beam({2024, 5, 10}, 1, lat, 3.0, {0, 0, 1}, 1.0);
        EXPECT_NEAR(out[kBeam] / ref, 1.0, 3e-3) << "latitude " << lat;
        // An open flat texel sees the whole sky and no ground.
        EXPECT_NEAR(out[kReflected], 0.0, 1e-6);
    }
}

// The 21st of every month of a year (12 one-day periods), summed.
TEST(InsolationModel, NorthFacingThirtyDegreeSlopeThroughTheYear) {
    InsolationSettings s = day_settings({2024, 1, 21}, 3.0, 2.0, false);
    s.periods.clear();
    for (int m = 1; m <= 12; ++m) s.periods.push_back(make_periods({2024, m, 21}, {2024, m, 21}, PeriodSplit::day, 0.0)[0]);
    const glm::dvec3 n(0.0, std::sin(radians(30.0)), std::cos(radians(30.0)));
    const auto slope = texel_of(s, 45.0, 0.0, glm::vec3(n), 0.0f);
    const auto flat = texel_of(s, 45.0, 0.0, {0, 0, 1}, 0.0f);
    double beam = 0, flat_beam = 0, ref = 0;
    for (int m = 1; m <= 12; ++m) {
        beam += slope[std::size_t(m - 1) * kQuantities + kBeam];
        flat_beam += flat[std::size_t(m - 1) * kQuantities + kBeam];
        ref += spa_beam({2024, m, 21}, 1, 45.0, 3.0, n, 2.0);
    }
    EXPECT_NEAR(beam / ref, 1.0, 5e-3);
    EXPECT_LT(beam, 0.75 * flat_beam);  // a north slope at 45 N gets far less
    EXPECT_EQ(slope[11 * kQuantities + kBeam], 0.0f);  // in December the sun never clears its plane
    // Open ground around: r.sun's isotropic slope, sky (1 + cos b) / 2, ground (1 - cos b) / 2.
    EXPECT_NEAR(tilted_sky_view_factor(std::vector<float>(128, 0.0f).data(), 128, n), (1 + std::cos(radians(30.0))) / 2,
                1e-3);
}

// Bands 5 degrees apart, a texel half way: linear between the two bands against a band at its
// own latitude (the year on flat open ground); the nearest band alone would be off by percents.
TEST(InsolationModel, LatitudeBandsInterpolateLinearly) {
    InsolationSettings s = day_settings({2024, 1, 1}, 3.0, 10.0, true);
    s.periods = make_periods({2024, 1, 1}, {2024, 12, 31}, PeriodSplit::year, 0.0);
    s.interpolate_bands = true;
    const InsolationModel coarse(s, 40.0, 50.0, 5.0, 0.0, 0.0, 1000.0);
    const auto [band, weight] = coarse.band_between(42.5);
    EXPECT_EQ(band, 0);
    EXPECT_FLOAT_EQ(weight, 0.5f);
    const InsolationModel::TexelInfo info{{0, 0, 1}, band, 0.0f, weight};
    const float svf = 1.0f;
    std::vector<float> out(kQuantities), nearest(kQuantities);
    coarse.run(1, &info, [&](int, float* h) { h[0] = 0.0f; }, &svf, out.data());
    const InsolationModel::TexelInfo info_nearest{{0, 0, 1}, coarse.band_of(42.5), 0.0f, 0.0f};
    coarse.run(1, &info_nearest, [&](int, float* h) { h[0] = 0.0f; }, &svf, nearest.data());
    const auto exact = texel_of(s, 42.5, 0.0, {0, 0, 1}, 0.0f);
    EXPECT_NEAR(out[kGlobal] / exact[kGlobal], 1.0, 3e-3);
    EXPECT_GT(std::abs(nearest[kGlobal] / exact[kGlobal] - 1.0), 0.01);
}

TEST(InsolationModel, PolarNightAndPolarDay) {
    const auto night = texel_of(day_settings({2024, 12, 21}, 3.0, 2.0, true), 80.0, 0.0, {0, 0, 1});
    EXPECT_EQ(night[kSunHours], 0.0f);
    EXPECT_EQ(night[kGlobal], 0.0f);
    const auto day = texel_of(day_settings({2024, 6, 21}, 3.0, 2.0, true), 80.0, 0.0, {0, 0, 1});
    EXPECT_NEAR(day[kSunHours], 24.0, 1e-3);
    EXPECT_GT(day[kBeam], 0.0f);
}

// A deep V valley running north-south, walls at 40 degrees: from its floor the horizon toward
// internal azimuth phi is atan(tan 40 |cos phi|). Hours of sun on the floor against that
// analytic horizon, integrated every 10 s.
TEST(InsolationModel, DeepVValleyHoursOfSun) {
    const int w = 61, h = 161;
    const double dx = 30.0, tan_wall = std::tan(radians(40.0));
    std::vector<float> z(std::size_t(w) * h);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) z[std::size_t(r) * w + c] = float(std::abs(c - w / 2) * dx * tan_wall);
    const terrain::HeightGrid grid = terrain::HeightGrid::uniform(w, h, z, dx, dx);
    visibility::HorizonOptions ho;
    ho.directions = 64;
    ho.curvature = false;
    ho.threads = 1;
    const visibility::HorizonSet set = visibility::compute_horizons(grid, ho);
    const render::NormalField normals = render::terrain_normals(grid, 1);
    const std::size_t floor_texel = std::size_t(h / 2) * w + w / 2;
    for (const CalendarDate day : {CalendarDate{2024, 3, 20}, CalendarDate{2024, 6, 21}, CalendarDate{2024, 12, 21}}) {
        auto s = day_settings(day, 3.0, 1.0, true);
        s.azimuth_bins = 4 * ho.directions;
        s.svf_stride = 4;
        const InsolationModel model(s, 45.0, 45.0, 0.1, 0.0, 0.0, 500.0);
        std::vector<float> bins(std::size_t(s.azimuth_bins)), out(kQuantities);
        bin_horizons(set, floor_texel, s.azimuth_bins, bins.data());
        model.texel(bins.data(), {normals.x[floor_texel], normals.y[floor_texel], normals.z[floor_texel]}, 0, 0.0,
                    out.data());
        double hours = 0;
        const auto begin = local_midnight(day, 0.0);
        for (int i = 0; i < 8640; ++i) {
            light::SunPositionInput in;
            in.time = begin + std::chrono::seconds(10 * i + 5);
            in.observer.latitude_deg = 45.0;
            const light::SunPosition p = light::sun_position(in);
            if (p.elevation_deg <= 0) continue;
            const double phi = radians(90.0 - p.azimuth_deg);
            const double horizon = std::atan(tan_wall * std::abs(std::cos(phi)));
            hours += visibility::sun_disc_visible_fraction(horizon, radians(p.elevation_deg), s.sun_radius_rad) / 360.0;
        }
        EXPECT_NEAR(out[kSunHours], hours, 5.0 / 60.0) << day.month << "-" << day.day;
        EXPECT_GT(hours, 0.3);
    }
}

}  // namespace
}  // namespace ts::solar
