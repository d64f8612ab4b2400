// The physical clear sky (core/light/physical_sky.hpp): against Blender's Nishita sky (the same
// single-scattering physics, stored by scripts/nishita_sky_reference.sh), its table against its
// own integral, the colours of a low sun, twilight and the disc's reddening.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "core/light/atmosphere.hpp"
#include "core/light/physical_sky.hpp"
#include "core/light/preetham_sky.hpp"
#include "core/light/sky_color.hpp"
#include "core/light/sky_quadrature.hpp"
#include "core/light/sun_transmittance.hpp"
#include "core/util/angles.hpp"

namespace ts::light {
namespace {

// ENU direction at an elevation and an azimuth clockwise from north (degrees).
glm::dvec3 direction(double elevation_deg, double azimuth_deg) {
    const double e = elevation_deg * kPi / 180.0, a = azimuth_deg * kPi / 180.0;
    return {std::cos(e) * std::sin(a), std::cos(e) * std::cos(a), std::sin(e)};
}

struct NishitaSample {
    double sun_elevation, view_elevation, rel_azimuth, x, y, Y_kcd;
};

std::vector<NishitaSample> read_nishita_reference() {
    std::ifstream in(std::string(TS_SOURCE_DIR) + "/tests/light/reference/nishita_sky_default.csv");
    std::vector<NishitaSample> out;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#' || line[0] == 's') continue;
        std::istringstream s(line);
        NishitaSample n{};
        char comma = 0;
        s >> n.sun_elevation >> comma >> n.view_elevation >> comma >> n.rel_azimuth >> comma >> n.x >> comma >> n.y >> comma >>
            n.Y_kcd;
        n.Y_kcd *= 0.683;  // Blender's Y = 1 is 683 cd/m^2
        out.push_back(n);
    }
    return out;
}

// Blender's default atmosphere: grey dust, vertical extinction 2.22e-5 /m over a 1.2 km scale height.
constexpr Aerosol kBlenderDefaultDust{2.22e-5 * 1200.0, 0.0};

constexpr double kLowestComparedDeg = 6.0;

TEST(PhysicalSky, AgreesWithBlendersNishitaSkyInColourAndLuminance) {
    const std::vector<NishitaSample> ref = read_nishita_reference();
    ASSERT_GT(ref.size(), 800u);
    double worst_xy = 0.0, worst_xy_near_sun = 0.0, sum_log2 = 0.0;
    int n = 0;
    for (double sun_el : {0.0, 3.0, 10.0, 20.0, 45.0, 70.0}) {
        const PhysicalSky sky(kBlenderDefaultDust, 0.2, direction(sun_el, 0.0), Scattering::single);
        for (const NishitaSample& r : ref) {
            // Within a few degrees of the horizon Blender's dome is 30-50% darker and redder than
            // this model's integral, which is converged there (400 steps give the same): left
            // out until the cause is known (docs/lighting.md).
            if (r.sun_elevation != sun_el || r.view_elevation < kLowestComparedDeg) continue;
            const Rgb l = sky.sky_radiance(direction(r.view_elevation, r.rel_azimuth));
            const Chromaticity c = chromaticity_of(l);
            const double dxy = std::hypot(c.x - r.x, c.y - r.y);
            // Blender reads its own table up to 0.7 degree off the asked direction (its
            // half-texel conventions), which near a low sun's steep aureole shows in colour.
            const bool near_sun = r.rel_azimuth <= 10.0 && std::abs(r.view_elevation - sun_el) <= 6.0;
            double& worst = near_sun ? worst_xy_near_sun : worst_xy;
            worst = std::max(worst, dxy);
            sum_log2 += std::pow(std::log(luminance(l) / r.Y_kcd), 2.0);
            ++n;
        }
    }
    const double rms_log = std::sqrt(sum_log2 / n);
    std::printf("against Blender's Nishita (%d directions, sun 0..70 deg): xy within %.4f (%.4f near the sun), "
                "luminance RMS %.1f%%\n",
                n, worst_xy, worst_xy_near_sun, 100.0 * (std::exp(rms_log) - 1.0));
    EXPECT_LT(worst_xy, 0.02);
    EXPECT_LT(worst_xy_near_sun, 0.02);
    EXPECT_LT(rms_log, std::log(1.12));
}

struct PathTracedSample {
    int wavelength_index;
    double albedo, sun_elevation, view_elevation, azimuth_from_sun, single, total, stderr_;
};

std::vector<PathTracedSample> read_path_traced_reference() {
    std::ifstream in(std::string(TS_SOURCE_DIR) + "/tests/light/reference/sky_path_traced.csv");
    std::vector<PathTracedSample> out;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#' || line[0] == 'w') continue;
        std::istringstream s(line);
        PathTracedSample p{};
        char comma = 0;
        s >> p.wavelength_index >> comma >> p.albedo >> comma >> p.sun_elevation >> comma >> p.view_elevation >> comma >>
            p.azimuth_from_sun >> comma >> p.single >> comma >> p.total >> comma >> p.stderr_;
        out.push_back(p);
    }
    return out;
}

// One wavelength's coefficients at every sample: the sky's luminance over the solar constant's
// is then that wavelength's radiance per unit extraterrestrial irradiance, as the path tracer's.
atmosphere::Coefficients monochromatic(int wavelength_index) {
    const atmosphere::Coefficients c = atmosphere::coefficients_for({angstrom_beta(3.0), 1.3});
    const std::size_t k = std::size_t(wavelength_index);
    atmosphere::Coefficients m;
    m.rayleigh.fill(c.rayleigh[k]);
    m.mie_scattering.fill(c.mie_scattering[k]);
    m.mie_extinction.fill(c.mie_extinction[k]);
    m.ozone.fill(c.ozone[k]);
    return m;
}

// Light scattered any number of times against a Monte Carlo path tracer of the same atmosphere
// (tests/light/sky_path_tracer.cpp, stored by scripts/sky_path_traced_reference.sh): 450 and
// 550 nm, ground albedo 0.2 and 0.8, sun 2-60 degrees, the dome in seven directions (the
// aureole among them) and its irradiance on level ground. The path tracer's own first order checks this sky's single
// scattering; the whole against the whole checks Hillaire's isotropic approximation.
TEST(PhysicalSky, AgreesWithAPathTracerWhenLightScattersManyTimes) {
    const std::vector<PathTracedSample> ref = read_path_traced_reference();
    ASSERT_EQ(ref.size(), 128u);
    double sum_log2_multiple = 0.0, sum_log2_single = 0.0, sum_log2_first = 0.0, worst_multiple = 0.0,
           worst_irradiance = 0.0;
    std::unique_ptr<PhysicalSky> multiple_sky, single_sky;  // made again when the scene changes
    const PathTracedSample* scene = nullptr;
    for (const PathTracedSample& r : ref) {
        if (!scene || scene->wavelength_index != r.wavelength_index || scene->albedo != r.albedo ||
            scene->sun_elevation != r.sun_elevation) {
            const glm::dvec3 sun = direction(r.sun_elevation, 0.0);
            multiple_sky = std::make_unique<PhysicalSky>(monochromatic(r.wavelength_index), r.albedo, sun, Scattering::multiple);
            single_sky = std::make_unique<PhysicalSky>(monochromatic(r.wavelength_index), r.albedo, sun, Scattering::single);
            scene = &r;
        }
        const PhysicalSky& multiple = *multiple_sky;
        const PhysicalSky& single = *single_sky;
        const bool irradiance = r.view_elevation < -45.0;
        const auto value = [&](const PhysicalSky& sky) {
            const Rgb l = irradiance ? sky.sky_horizontal_irradiance()
                                     : sky.sky_radiance(direction(r.view_elevation, r.azimuth_from_sun));
            return luminance(l) / kSolarIlluminanceKlx;
        };
        const double m = value(multiple), s = value(single);
        const double err = std::log(m / r.total);
        if (std::abs(err) > std::log(1.2)) std::printf("%3.0f nm albedo %.1f sun %4.1f view %5.1f/%5.1f: path traced %.4e (+-%.1f%%) multiple %+6.1f%% "
                    "single %+6.1f%% (first order %+6.1f%%)\n",
                    atmosphere::wavelength_nm(r.wavelength_index), r.albedo, r.sun_elevation, r.view_elevation,
                    r.azimuth_from_sun, r.total, 100.0 * r.stderr_ / r.total, 100.0 * (m / r.total - 1.0),
                    100.0 * (s / r.total - 1.0), 100.0 * (s / r.single - 1.0));
        sum_log2_multiple += err * err;
        sum_log2_single += std::pow(std::log(s / r.total), 2.0);
        sum_log2_first += std::pow(std::log(s / r.single), 2.0);
        worst_multiple = std::max(worst_multiple, std::abs(err));
        if (irradiance) worst_irradiance = std::max(worst_irradiance, std::abs(err));
    }
    const auto rms = [&](double sum) { return std::exp(std::sqrt(sum / double(ref.size()))) - 1.0; };
    std::printf("against the path tracer (%zu rows): multiple scattering RMS %.1f%% (worst %.1f%%, irradiance worst "
                "%.1f%%); single scattering RMS %.1f%% against the whole, %.1f%% against the first order\n",
                ref.size(), 100.0 * rms(sum_log2_multiple), 100.0 * (std::exp(worst_multiple) - 1.0),
                100.0 * (std::exp(worst_irradiance) - 1.0), 100.0 * rms(sum_log2_single), 100.0 * rms(sum_log2_first));
    // The path tracer's first order is this sky's single scattering (its noise is 0.3-1.3%).
    EXPECT_LT(rms(sum_log2_first), 0.03);
    // All orders: off most beside a setting sun (+27-37% 5 degrees from it), a few degrees up
    // at a low sun (+25-32% at 550 nm) and over snow under a high sun (+20-30%); without them
    // the dome is 3-20x too dark there (single scattering: RMS ~230%).
    EXPECT_LT(rms(sum_log2_multiple), 0.12);
    EXPECT_LT(std::exp(worst_multiple) - 1.0, 0.40);
    EXPECT_LT(std::exp(worst_irradiance) - 1.0, 0.20);
}

TEST(PhysicalSky, TableMatchesItsOwnIntegral) {
    double worst = 0.0;
    for (double sun_el : {-3.0, 2.0, 15.0, 60.0}) {
        const PhysicalSky sky(3.0, 0.2, direction(sun_el, 200.0));
        const double zenith = luminance(sky.sky_radiance_integrated(glm::dvec3(0.0, 0.0, 1.0)));
        for (double el : {1.0, 3.0, 7.0, 25.0, 50.0, 85.0}) {
            for (double az = 0.0; az < 360.0; az += 37.0) {
                const glm::dvec3 d = direction(el, az);
                const double table = luminance(sky.sky_radiance(d));
                const double exact = luminance(sky.sky_radiance_integrated(d));
                // Relative to the larger of the value and the zenith's: dark corners of a
                // twilight sky are compared by what they add to the picture.
                worst = std::max(worst, std::abs(table - exact) / std::max(exact, zenith));
            }
        }
    }
    std::printf("table against the integral: worst %.2f%%\n", 100.0 * worst);
    EXPECT_LT(worst, 0.03);
}

TEST(PhysicalSky, LowSunIsOrangeWherePreethamIsYellow) {
    // The case: sun 3 degrees up, the sky 4 degrees up beside it.
    const glm::dvec3 sun = direction(3.0, 270.0);
    const Chromaticity physical = chromaticity_of(PhysicalSky(3.0, 0.2, sun).sky_radiance(direction(4.0, 270.0)));
    const Chromaticity preetham = chromaticity_of(PreethamSky(3.0, 0.2, sun).sky_radiance(direction(4.0, 270.0)));
    EXPECT_GT(physical.x, 0.45);  // orange: x above y, both near 0.43-0.5
    EXPECT_GT(physical.x - physical.y, 0.02);
    EXPECT_GT(physical.x - preetham.x, 0.03);
    // The zenith stays blue.
    const Chromaticity zenith = chromaticity_of(PhysicalSky(3.0, 0.2, sun).sky_radiance(glm::dvec3(0.0, 0.0, 1.0)));
    EXPECT_LT(zenith.x, 0.29);
    EXPECT_LT(zenith.y, 0.31);
}

TEST(PhysicalSky, TheDiscReddensAndDimsTowardsTheHorizonAndSetsAtIt) {
    double last_ratio = 1e9, last_luminance = 1e9;
    for (double el : {70.0, 45.0, 20.0, 10.0, 3.0, 0.5}) {
        const Rgb e = PhysicalSky(3.0, 0.2, direction(el, 90.0)).sun().irradiance;
        const double ratio = e.b / e.r;
        EXPECT_LE(ratio, last_ratio) << el;
        EXPECT_LT(luminance(e), last_luminance) << el;
        last_ratio = ratio;
        last_luminance = luminance(e);
    }
    // Clear-sky direct normal illuminance at a high sun: measured ~80-100 klx.
    const double high = luminance(PhysicalSky(3.0, 0.2, direction(60.0, 90.0)).sun().irradiance);
    EXPECT_GT(high, 70.0);
    EXPECT_LT(high, 115.0);
    // The same turbidity gives nearly the beam of the disc model Preetham's sky uses (the same
    // optical depths along a spherical path instead of Kasten & Young's air mass, and ozone,
    // which that model leaves out: 0.944 at 30 degrees).
    const double preetham = luminance(sun_beam_irradiance(3.0, direction(30.0, 90.0), 0.004654));
    const double physical = luminance(PhysicalSky(3.0, 0.2, direction(30.0, 90.0)).sun().irradiance);
    EXPECT_NEAR(physical / preetham, 0.96, 0.03);
    EXPECT_EQ(luminance(PhysicalSky(3.0, 0.2, direction(-1.0, 90.0)).sun().irradiance), 0.0);
}

TEST(PhysicalSky, TwilightIsSkyLitBlueAndContinuous) {
    const auto zenith = [](double sun_el) {
        return PhysicalSky(3.0, 0.2, direction(sun_el, 90.0)).sky_radiance(glm::dvec3(0.0, 0.0, 1.0));
    };
    const Rgb civil = zenith(-4.0);
    EXPECT_GT(luminance(civil), 1e-3);  // > 1 cd/m^2: a sky, not black
    EXPECT_LT(chromaticity_of(civil).x, 0.29);
    // A degree of sun costs the zenith about a third near sunset (measured twilight skies lose
    // ~10x in luminance from 0 to -6 degrees): no cliff at the horizon.
    const double below = luminance(zenith(-0.5)), above = luminance(zenith(0.5));
    EXPECT_GT(below / above, 0.5);
    EXPECT_LT(below / above, 1.0);
    // Darker monotonically as the sun sinks.
    double last = 1e9;
    for (double el = 2.0; el >= -6.0; el -= 1.0) {
        const double y = luminance(zenith(el));
        EXPECT_LT(y, last) << el;
        last = y;
    }
}

TEST(PhysicalSky, GroundIsAlbedoTimesIrradianceOverPi) {
    const glm::dvec3 sun = direction(30.0, 120.0);
    const PhysicalSky sky(3.0, 0.25, sun);
    const Rgb e = sky.sky_horizontal_irradiance() + sky.sun().irradiance * static_cast<float>(sun.z);
    const Rgb g = sky.radiance(glm::dvec3(0.3, 0.2, -0.9));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(g[c], 0.25 * e[c] / kPi, 1e-4 * e[c]);
    // A clear sky's diffuse share of the light on level ground with the sun 30 degrees up: 15-40%
    // (measured clear skies; 0.36 at turbidity 3, where the path tracer's irradiance at 450 and
    // 550 nm is within 5% of this sky's).
    const double share = luminance(sky.sky_horizontal_irradiance()) / luminance(e);
    EXPECT_GT(share, 0.15);
    EXPECT_LT(share, 0.40);
}

TEST(PhysicalSky, TheAureoleLitWithTheSunKeepsLevelGroundsLightAndThePicture) {
    // light_aureole_with_sun moves the circumsolar peak from the dome that shades into the sun's
    // beam: level ground gets the same light (within 0.5%; the cap's SH-free integral against
    // the dome's rule), the sky as pictured keeps it, and the disc as drawn is the beam's alone.
    for (double elevation : {8.0, 20.0, 50.0}) {
        const glm::dvec3 sun = direction(elevation, 135.0);
        const PhysicalSky whole(3.0, 0.3, sun);
        PhysicalSky lit(3.0, 0.3, sun);
        lit.light_aureole_with_sun(30.0);
        auto level = [&](const PhysicalSky& sky) {
            double e = 0.0;
            for_each_sky_node(HemisphereRule{96, 384}, false, [&](const glm::dvec3& d, double w) {
                e += luminance(sky.lighting_radiance(d)) * w * d.z;
            });
            return e + luminance(sky.sun().irradiance) * sun.z;
        };
        EXPECT_NEAR(level(lit), level(whole), 0.005 * level(whole)) << elevation;
        EXPECT_EQ(whole.sun().aureole, Rgb(0.0f));
        const double share = luminance(lit.sun().aureole) / luminance(lit.sun().irradiance);
        EXPECT_GT(share, 0.02) << elevation;  // measured: 0.038, 0.130, 0.104
        EXPECT_LT(share, 0.25) << elevation;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(lit.sun().disc_irradiance()[c], whole.sun().irradiance[c], 1e-5f);
        const glm::dvec3 beside = direction(elevation + 3.0, 140.0), far = direction(60.0, 315.0);
        EXPECT_EQ(lit.radiance(beside), whole.radiance(beside));
        // Measured: 0.86, 0.31 and 0.15 of it, 5.8 degrees from the sun (the cap is 8 degrees wide at 8).
        EXPECT_LT(luminance(lit.lighting_radiance(beside)), 0.9 * luminance(whole.radiance(beside)));
        EXPECT_EQ(lit.lighting_radiance(far), whole.radiance(far));
    }
    // The cap never reaches below the horizon: with the sun at the horizon nothing moves.
    PhysicalSky low(3.0, 0.3, direction(0.2, 135.0));
    low.light_aureole_with_sun(30.0);
    EXPECT_EQ(low.sun().aureole, Rgb(0.0f));
}

}  // namespace
}  // namespace ts::light
