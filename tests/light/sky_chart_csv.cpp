// Prints the data behind docs/charts/sky_*.png (scripts/chart_sky.py runs it):
//   sky_chart_csv OUT_DIR  ->  OUT_DIR/sky_profile.csv, OUT_DIR/sky_sh.csv, OUT_DIR/sky_low_sun.csv
// sky_profile: luminance and RGB along the sun's vertical plane (signed zenith angle, positive
// towards the sun) for several turbidities of the clear sky (Preetham), the physical sky at T = 3
// and the overcast sky, sun 30 degrees up.
// sky_low_sun: CIE xy and luminance along the sun's vertical with the sun 3 and 20 degrees up,
// for the physical sky (T = 3, all orders and single scattering; single scattering with
// Blender's default dust), Preetham's (T = 3).
// sky_sh: the same profile for the clear (Preetham, T = 3), physical (T = 3) and overcast skies
// beside their order-4 SH reconstruction.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/geo/azimuth.hpp"
#include "core/light/overcast_sky.hpp"
#include "core/light/physical_sky.hpp"
#include "core/light/preetham_sky.hpp"
#include "core/light/sky_color.hpp"
#include "core/light/sky_sh.hpp"
#include "core/util/angles.hpp"

using namespace ts::light;
using ts::radians;

namespace {
constexpr double kSunAzimuth = 180.0;
constexpr double kSunElevation = 30.0;

// Signed zenith angle z in [-90, 90]: positive towards the sun's azimuth.
glm::dvec3 vertical_dir(double signed_zenith_deg) {
    const double az = signed_zenith_deg >= 0 ? kSunAzimuth : kSunAzimuth + 180.0;
    return ts::geo::enu_direction(ts::geo::azimuth_cw_from_north_to_phi(az),
                                  radians(90.0 - std::abs(signed_zenith_deg)));
}
}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: sky_chart_csv OUT_DIR\n");
        return 2;
    }
    const std::filesystem::path dir = argv[1];
    const glm::dvec3 sun =
        ts::geo::enu_direction(ts::geo::azimuth_cw_from_north_to_phi(kSunAzimuth), radians(kSunElevation));

    std::ofstream profile(dir / "sky_profile.csv");
    profile << "sky,turbidity,signed_zenith_deg,luminance,r,g,b\n";
    const double turbidities[] = {2.0, 3.0, 5.0, 8.0};
    for (double t : turbidities) {
        const PreethamSky sky(t, 0.2, sun);
        for (double z = -89.5; z <= 89.5; z += 1.0) {
            const Rgb l = sky.radiance(vertical_dir(z));
            profile << "clear," << t << ',' << z << ',' << luminance(l) << ',' << l.r << ',' << l.g << ',' << l.b
                    << '\n';
        }
    }
    const PhysicalSky physical(3.0, 0.2, sun);
    for (double z = -89.5; z <= 89.5; z += 1.0) {
        const Rgb l = physical.radiance(vertical_dir(z));
        profile << "physical,3," << z << ',' << luminance(l) << ',' << l.r << ',' << l.g << ',' << l.b << '\n';
    }
    const OvercastSky overcast(1.0, 0.2, sun);
    for (double z = -89.5; z <= 89.5; z += 1.0) {
        const Rgb l = overcast.radiance(vertical_dir(z));
        profile << "overcast,0," << z << ',' << luminance(l) << ',' << l.r << ',' << l.g << ',' << l.b << '\n';
    }

    std::ofstream shcsv(dir / "sky_sh.csv");
    shcsv << "sky,signed_zenith_deg,true_luminance,sh_luminance\n";
    const PreethamSky clear(3.0, 0.2, sun);
    const Sky* skies[] = {&clear, &physical, &overcast};
    const char* names[] = {"clear T=3", "physical T=3", "overcast"};
    for (int k = 0; k < 3; ++k) {
        const SkySh sh = project_sky_sh(*skies[k]);
        // The whole circle: the vertical plane continues below the horizon (the ground).
        for (double a = -179.5; a <= 179.5; a += 1.0) {
            const double z = a;  // signed angle from the zenith, beyond +-90 below the horizon
            const double phi = ts::geo::azimuth_cw_from_north_to_phi(kSunAzimuth);
            const glm::dvec3 d(std::sin(radians(z)) * std::cos(phi), std::sin(radians(z)) * std::sin(phi),
                               std::cos(radians(z)));
            shcsv << names[k] << ',' << z << ',' << luminance(skies[k]->radiance(d)) << ','
                  << luminance(reconstruct_sky_sh(sh, d)) << '\n';
        }
    }
    std::ofstream low(dir / "sky_low_sun.csv");
    low << "sky,sun_elevation_deg,signed_zenith_deg,x,y,luminance\n";
    for (double e : {3.0, 20.0}) {
        const glm::dvec3 s = ts::geo::enu_direction(ts::geo::azimuth_cw_from_north_to_phi(kSunAzimuth), radians(e));
        const PhysicalSky physical_t3(3.0, 0.2, s);
        const PhysicalSky single_t3(3.0, 0.2, s, Scattering::single);
        const PhysicalSky blender_dust(Aerosol{2.22e-5 * 1200.0, 0.0}, 0.2, s, Scattering::single);
        const PreethamSky fitted(3.0, 0.2, s);
        const Sky* models[] = {&physical_t3, &single_t3, &blender_dust, &fitted};
        const char* labels[] = {"physical T=3", "physical T=3 single scattering", "single scattering with Blender's dust",
                                "Preetham T=3"};
        for (int k = 0; k < 4; ++k) {
            for (double z = -89.5; z <= 89.5; z += 0.5) {
                const Rgb l = models[k]->radiance(vertical_dir(z));
                const Chromaticity xy = chromaticity_of(l);
                low << labels[k] << ',' << e << ',' << z << ',' << xy.x << ',' << xy.y << ',' << luminance(l) << '\n';
            }
        }
    }
    std::printf("wrote %s, %s and %s\n", (dir / "sky_profile.csv").c_str(), (dir / "sky_sh.csv").c_str(),
                (dir / "sky_low_sun.csv").c_str());
    return 0;
}
