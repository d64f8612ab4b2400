// Writes terrashade's own sky as an equirectangular float32 map and its sun as JSON, so that an
// outside renderer (scripts/cycles_reference.py, Blender Cycles) lights a scene with exactly the
// radiance and sun irradiance `render --sky SPEC --sun-azimuth A --sun-elevation E` uses
// (docs/accuracy.md, "Against Blender Cycles"). Not a test.
//
//   sky_equirect_dump SKY_SPEC AZIMUTH_DEG ELEVATION_DEG WIDTH OUT_PREFIX
//     -> OUT_PREFIX.f32  WIDTH x WIDTH/2 x RGB float32, row-major, row 0 the zenith
//        OUT_PREFIX.json width, height, the sun's direction, angular radius and RGB irradiance
//
// Column layout is Blender's equirectangular one, not terrashade's HDR reader's: column u
// (pixel centre (j + 0.5) / WIDTH) faces azimuth 90 + (u - 0.5) x 360 degrees clockwise from
// north, i.e. the centre column faces east (+x) and u grows clockwise seen from above. Row i's
// centre is at zenith angle (i + 0.5) / HEIGHT x 180 degrees. The sun's disc is not in the map
// (Sky::radiance excludes it); the sun goes into a separate lamp.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "core/geo/azimuth.hpp"
#include "core/light/sky.hpp"
#include "core/util/angles.hpp"

using namespace ts::light;

int main(int argc, char** argv) {
    if (argc != 6) {
        std::fprintf(stderr, "usage: sky_equirect_dump SKY_SPEC AZIMUTH_DEG ELEVATION_DEG WIDTH OUT_PREFIX\n");
        return 2;
    }
    const SkyOptions options = parse_sky_options(argv[1]);
    const double azimuth = std::stod(argv[2]), elevation = std::stod(argv[3]);
    const int width = std::stoi(argv[4]), height = width / 2;
    const std::string prefix = argv[5];
    // The same direction `render --sun-azimuth --sun-elevation` gives its sky (render_scene.cpp).
    const glm::dvec3 sun_dir =
        ts::geo::enu_direction(ts::geo::azimuth_cw_from_north_to_phi(azimuth), ts::radians(elevation));
    const auto sky = make_sky(options, sun_dir);

    std::vector<float> pixels(static_cast<size_t>(width) * height * 3);
    for (int i = 0; i < height; ++i) {
        const double zenith = (i + 0.5) / height * 180.0;
        for (int j = 0; j < width; ++j) {
            const double az = 90.0 + ((j + 0.5) / width - 0.5) * 360.0;
            const glm::dvec3 d = ts::geo::enu_direction(ts::geo::azimuth_cw_from_north_to_phi(az),
                                                        ts::radians(90.0 - zenith));
            const Rgb l = sky->radiance(d);
            float* p = &pixels[(static_cast<size_t>(i) * width + j) * 3];
            p[0] = l.r, p[1] = l.g, p[2] = l.b;
        }
    }
    std::ofstream(prefix + ".f32", std::ios::binary)
        .write(reinterpret_cast<const char*>(pixels.data()), static_cast<std::streamsize>(pixels.size() * 4));

    // The disc alone: the map holds the whole dome, aureole included.
    const SunDisc sun = sky->sun();
    const Rgb disc = sun.disc_irradiance();
    std::FILE* json = std::fopen((prefix + ".json").c_str(), "w");
    if (!json) return 1;
    std::fprintf(json,
                 "{\"sky\": \"%s\", \"width\": %d, \"height\": %d, \"sun_azimuth_deg\": %.9g, "
                 "\"sun_elevation_deg\": %.9g, \"sun_direction_enu\": [%.12g, %.12g, %.12g], "
                 "\"sun_angular_radius_rad\": %.9g, \"sun_irradiance_rgb\": [%.9g, %.9g, %.9g]}\n",
                 sky->describe().c_str(), width, height, azimuth, elevation, sun.direction.x, sun.direction.y,
                 sun.direction.z, sun.angular_radius_rad, disc.r, disc.g, disc.b);
    std::fclose(json);
    std::printf("wrote %s.f32 and %s.json\n", prefix.c_str(), prefix.c_str());
    return 0;
}
