// The flythrough's offscreen frames (gpu/fly) over a shared DEM, with the validation layer on:
// terrain and sky present, no black frames, frames that change as the camera moves, and no
// crack pixels (sky seen through the terrain) between LOD patches; an aircraft low in a valley
// darker than the same aircraft high in the open sky; the Cessna's sun shadow on a slope where
// the sun predicts it, and nothing changed elsewhere.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "core/blockers/sphere_decomposition.hpp"
#include "core/blockers/sphere_occlusion_shared.hpp"
#include "core/blockers/sun_disc_occlusion.hpp"
#include "core/dem/read_dem.hpp"
#include "core/fly/fly_camera.hpp"
#include "core/mesh/mesh_import.hpp"
#include "core/fly/flight_path.hpp"
#include "core/light/utc_time.hpp"
#include "core/raster/png_writer.hpp"
#include "core/raster/srgb.hpp"
#include "core/render/tone_map.hpp"
#include "gpu/fly/flythrough.hpp"
#include "tests/gpu/crack_pixels.hpp"
#include "tests/gpu/validated_context.hpp"

namespace ts::gpu {
namespace {

class FlyRenderTest : public test_support::ValidatedTest {};

struct FrameCheck {
    double terrain_fraction = 0, sky_fraction = 0;
    double terrain_mean = 0, sky_mean = 0;
    double black_terrain_fraction = 0;
    int crack_pixels = 0;
};

// depth > 0: terrain drawn (reversed Z, cleared to 0); cracks as tests/gpu/crack_pixels.hpp counts them.
FrameCheck check_frame(const std::vector<std::uint8_t>& rgba, const std::vector<float>& depth, int w, int h) {
    FrameCheck c;
    std::size_t terrain = 0, sky = 0, black = 0;
    double sum = 0, sky_sum = 0;
    for (std::size_t i = 0; i < std::size_t(w) * std::size_t(h); ++i) {
        const double r = rgba[4 * i], g = rgba[4 * i + 1], b = rgba[4 * i + 2];
        if (depth[i] > 0.0f) {
            ++terrain;
            sum += (r + g + b) / 3.0;
            if (r + g + b == 0) ++black;
        } else {
            ++sky;
            sky_sum += (r + g + b) / 3.0;
        }
    }
    const double n = double(w) * double(h);
    c.terrain_fraction = double(terrain) / n;
    c.sky_fraction = double(sky) / n;
    c.terrain_mean = terrain ? sum / double(terrain) : 0;
    c.sky_mean = sky ? sky_sum / double(sky) : 0;
    c.black_terrain_fraction = terrain ? double(black) / double(terrain) : 0;
    c.crack_pixels = test_support::crack_pixels(depth, w, h);
    return c;
}

TEST_F(FlyRenderTest, AShortFlightOverGrenobleHasTerrainSkyAndNoCracks) {
    const dem::Dem dem = dem::read_dem(std::string(TS_SHARED_DATA) + "/dem/copernicus_N45E005_grenoble_500px.tif");
    FlySettings settings;
    settings.width = 480;
    settings.height = 270;
    settings.directions = 8;
    Flythrough flight(dem, settings, *context_);
    flight.set_time(light::parse_utc_time("2024-06-21T08:00:00Z"));
    // From the DEM's south-west quarter towards its centre, heading north-east, slightly down.
    const glm::dvec2 a = dem.georef.pixel_to_lonlat(0.25 * dem.width, 0.75 * dem.height);
    const glm::dvec2 b = dem.georef.pixel_to_lonlat(0.45 * dem.width, 0.55 * dem.height);
    const fly::FlightPath path({{0, a.x, a.y, 2600, 45, -8, 0}, {10, b.x, b.y, 2400, 50, -10, 0}});
    std::vector<std::uint8_t> rgba, previous;
    std::vector<float> depth;
    int levels_drawn = 0;
    for (int i = 0; i < 4; ++i) {
        const fly::CameraPose pose = flight.pose_of(path.at(10.0 * i / 3.0));
        FlyFrameUniforms u;
        FlyFrameStats stats;
        flight.prepare(pose, u, stats);
        int lo = 99, hi = -1;
        for (const auto& p : flight.patches()) lo = std::min(lo, p.level), hi = std::max(hi, p.level);
        levels_drawn = std::max(levels_drawn, hi - lo + 1);
        flight.renderer().render_to_memory(u, flight.patches(), rgba, &depth);
        const FrameCheck c = check_frame(rgba, depth, settings.width, settings.height);
        SCOPED_TRACE("frame " + std::to_string(i));
        EXPECT_GT(c.terrain_fraction, 0.3);
        EXPECT_GT(c.sky_fraction, 0.05);
        EXPECT_GT(c.terrain_mean, 25.0);        // lit, not black
        EXPECT_LT(c.black_terrain_fraction, 0.01);
        // A clear morning sky is brighter than the ground it lights, and not burnt out.
        EXPECT_GT(c.sky_mean, c.terrain_mean);
        EXPECT_LT(c.sky_mean, 252.0);
        EXPECT_EQ(c.crack_pixels, 0);
        EXPECT_LE(stats.screen_error_px, settings.lod.pixel_error * (1 + 1e-5));
        if (!previous.empty()) {
            double diff = 0;
            for (std::size_t k = 0; k < rgba.size(); ++k) diff += std::abs(int(rgba[k]) - int(previous[k]));
            EXPECT_GT(diff / double(rgba.size()), 2.0) << "the frame did not change as the camera moved";
        }
        previous = rgba;
    }
    EXPECT_GE(levels_drawn, 2);  // LOD levels meet in the frames: their seams are checked
}

// A flat white plate, 40 m square, facing up, in `cells` x `cells` squares of two triangles:
// its light is the sky it sees and the sun.
mesh::TriangleMesh plate(int cells = 1) {
    mesh::TriangleMesh m;
    const float a = 20.0f, step = 2.0f * a / float(cells);
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            const float x0 = -a + step * float(i), y0 = -a + step * float(j), x1 = x0 + step, y1 = y0 + step;
            for (const glm::vec3& q : {glm::vec3(x0, y0, 0), glm::vec3(x1, y0, 0), glm::vec3(x1, y1, 0),
                                       glm::vec3(x0, y0, 0), glm::vec3(x1, y1, 0), glm::vec3(x0, y1, 0)})
                m.positions.push_back(q);
            m.material.push_back(0), m.material.push_back(0);
        }
    m.normals.assign(m.positions.size(), glm::vec3(0, 0, 1));
    m.materials = {mesh::MeshMaterial{"white", glm::vec4(0.25f, 0.25f, 0.25f, 1.0f), ""}};
    return m;
}

// Mean display code of the pixels the aircraft changes, seen 60 m south and 60 m above it.
double aircraft_mean(Flythrough& flight, const glm::dvec3& at, const char* png) {
    fly::CameraPose aircraft;
    aircraft.eye = at;
    fly::CameraPose camera;
    camera.eye = at + glm::dvec3(0, -60, 60);
    camera.heading_deg = 0;
    camera.pitch_deg = -45;
    FlyFrameUniforms u;
    FlyFrameStats stats;
    std::vector<std::uint8_t> with, without;
    flight.prepare(camera, u, stats, &aircraft);
    flight.renderer().render_to_memory(u, flight.patches(), with);
    flight.prepare(camera, u, stats, nullptr);
    flight.renderer().render_to_memory(u, flight.patches(), without);
    if (const char* dir = std::getenv("TS_TEST_PNG_DIR"))
        raster::write_png(std::string(dir) + "/" + png, png, flight.renderer().width(), flight.renderer().height(), 4,
                          with.data());
    double sum = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i + 3 < with.size(); i += 4) {
        if (with[i] == without[i] && with[i + 1] == without[i + 1] && with[i + 2] == without[i + 2]) continue;
        sum += (with[i] + with[i + 1] + with[i + 2]) / 3.0;
        ++n;
    }
    EXPECT_GT(n, 500u) << png << ": the aircraft is not drawn";
    return n ? sum / double(n) : 0;
}

// The lowest texel of the DEM's middle (every 5th row and column) whose point 15 m above it the
// sun has left, as a grid index; -1 if none.
int shaded_valley_floor(const Flythrough& flight) {
    const terrain::HeightGrid& g = flight.scene().grid();
    const light::SunDisc sun = flight.scene().last_sky()->sun();
    const render::PointTerrainLighting probe(g);
    int low = -1;
    for (int r = g.height / 4; r < 3 * g.height / 4; r += 5)
        for (int c = g.width / 4; c < 3 * g.width / 4; c += 5) {
            const std::size_t i = std::size_t(r) * std::size_t(g.width) + std::size_t(c);
            if (low >= 0 && g.z[i] >= g.z[std::size_t(low)]) continue;
            if (probe.light({c, r}, g.z[i] + 15.0, light::SkySh{}, sun.direction, sun.angular_radius_rad).sun_fraction == 0)
                low = int(i);
        }
    return low;
}

TEST_F(FlyRenderTest, AnAircraftLowInAValleyIsDarkerThanInTheOpenSky) {
    const dem::Dem dem = dem::read_dem(std::string(TS_SHARED_DATA) + "/dem/copernicus_N45E005_grenoble_500px.tif");
    FlySettings settings;
    settings.width = 320;
    settings.height = 180;
    settings.directions = 16;
    Flythrough flight(dem, settings, *context_);
    flight.set_time(light::parse_utc_time("2024-12-21T14:45:00Z"));
    flight.set_aircraft(plate(), 1.0, 0.0);
    // A valley floor of the DEM's middle the sun has left and the highest point of the whole DEM.
    const terrain::HeightGrid& g = flight.scene().grid();
    const int low = shaded_valley_floor(flight);
    float top = -1e9f;
    for (float z : g.z) top = std::max(top, z);
    ASSERT_GE(low, 0) << "no shaded valley at this time";
    const glm::dvec2 m = flight.frame().to_metric(low % g.width, low / g.width);
    const glm::dvec3 valley(m.x, m.y, flight.ground_height_m({m.x, m.y, 0}) + 15.0);
    const glm::dvec3 open(m.x, m.y, double(top) + 2000.0);

    const double dark = aircraft_mean(flight, valley, "fly_aircraft_valley.png");
    const render::PointTerrainLight in_valley = flight.aircraft_terrain_light();
    const double bright = aircraft_mean(flight, open, "fly_aircraft_open.png");
    const render::PointTerrainLight in_open = flight.aircraft_terrain_light();
    std::printf("aircraft valley floor %.0f m: display mean %.1f, sun fraction %.2f, sky DC %.4f\n", valley.z, dark,
                in_valley.sun_fraction, in_valley.visible_sky[0].y);
    std::printf("aircraft open sky %.0f m: display mean %.1f, sun fraction %.2f, sky DC %.4f\n", open.z, bright,
                in_open.sun_fraction, in_open.visible_sky[0].y);
    // Ignoring the terrain would light both alike (the aircraft's shader has no haze).
    EXPECT_LT(in_valley.visible_sky[0].y, 0.9f * in_open.visible_sky[0].y);
    EXPECT_LT(dark, bright - 10.0);
    EXPECT_EQ(in_valley.sun_fraction, 0.0f);
    EXPECT_EQ(in_open.sun_fraction, 1.0f);
}

// Where a frame's terrain pixels are in the grid frame: depth (reversed Z) through the inverse
// eye-relative view-projection, plus the eye, with the curvature drop the vertex shader took
// added back. Sky pixels: no point.
std::vector<glm::dvec3> terrain_points(const FlyFrameUniforms& u, const glm::dvec3& eye, const std::vector<float>& depth,
                                       int w, int h, std::vector<bool>& is_terrain) {
    const glm::dmat4 inverse = glm::inverse(glm::dmat4(u.view_projection));
    std::vector<glm::dvec3> points(depth.size(), glm::dvec3(0.0));
    is_terrain.assign(depth.size(), false);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            if (!(depth[i] > 0.0f)) continue;
            const glm::dvec4 ndc((x + 0.5) / w * 2.0 - 1.0, (y + 0.5) / h * 2.0 - 1.0, double(depth[i]), 1.0);
            const glm::dvec4 q = inverse * ndc;
            glm::dvec3 rel = glm::dvec3(q) / q.w;
            rel.z += glm::dot(glm::dvec2(rel), glm::dvec2(rel)) / (2.0 * 7321644.0);
            points[i] = rel + eye;
            is_terrain[i] = true;
        }
    return points;
}

// The fraction of the sun's disc the placed spheres leave at a point (the blockers' CPU formula).
double sun_left(const std::vector<blockers::Sphere>& spheres, const glm::dvec3& p, const glm::dvec3& sun) {
    double visible = 1.0;
    for (const blockers::Sphere& s : spheres) visible *= 1.0 - blockers::sphere_sun_cover(s, p, sun);
    return visible;
}

// The shared Cessna (64 spheres) flies 40 m over the sunlit west face of the Belledonne on a
// June afternoon; the camera looks down at where its shadow falls, from the sun's side. The
// pixels the shadow must cover are found on the CPU: each terrain pixel of the frame without
// the aircraft back to the grid frame (its depth), and the sun's disc against the aircraft's
// spheres from there. Against the same frame without the aircraft: the umbra is darker, the
// pixels outside the sun cone and the sky footprint are bit-identical, none is brighter.
TEST_F(FlyRenderTest, TheCessnaCastsItsSunShadowWhereTheSunPredictsIt) {
    const dem::Dem dem = dem::read_dem(std::string(TS_SHARED_DATA) + "/dem/copernicus_N45E005_grenoble_500px.tif");
    const mesh::TriangleMesh cessna = mesh::import_mesh(std::string(TS_SHARED_DATA) + "/meshes/c172p.ac");
    blockers::DecompositionOptions d;
    d.count = 64;
    const blockers::SphereDecomposition spheres = blockers::decompose_into_spheres(cessna, d);
    FlySettings settings;
    settings.width = 480;
    settings.height = 270;
    settings.directions = 8;
    Flythrough flight(dem, settings, *context_);
    flight.set_time(light::parse_utc_time("2024-06-21T15:30:00Z"));
    flight.set_aircraft(cessna, 1.0, -90.0, spheres.spheres);
    // The sun's direction the shaders get (the sky's disc).
    FlyFrameUniforms first;
    FlyFrameStats first_stats;
    flight.prepare(flight.default_pose(), first, first_stats);
    const glm::dvec3 sun = glm::normalize(glm::dvec3(first.sun_direction));
    ASSERT_GT(sun.z, 0.3);
    const glm::dvec2 start_px = dem.georef.lonlat_to_pixel({5.845, 45.205});
    const glm::dvec2 start = flight.frame().to_metric(start_px.x - 0.5, start_px.y - 0.5);

    std::vector<std::uint8_t> with, without;
    std::vector<float> depth_with, depth_without;
    std::vector<bool> is_terrain;
    for (int frame = 0; frame < 3; ++frame) {
        SCOPED_TRACE("frame " + std::to_string(frame));
        // Northwards along the slope, 25 m a frame, 40 m above the ground under it.
        fly::CameraPose aircraft;
        aircraft.eye = glm::dvec3(start.x, start.y + 25.0 * frame, 0.0);
        aircraft.eye.z = flight.ground_height_m(aircraft.eye) + 40.0;
        aircraft.heading_deg = 0.0;
        aircraft.roll_deg = 10.0;
        // Where the shadow falls: down the sun's ray from the aircraft to the ground.
        glm::dvec3 shadow = aircraft.eye;
        while (shadow.z > flight.ground_height_m(shadow)) shadow -= sun * 0.5;
        fly::CameraPose camera;
        camera.eye = shadow + glm::dvec3(sun.x, sun.y, 0.0) / glm::length(glm::dvec2(sun)) * 60.0 + glm::dvec3(0, -25, 45);
        fly::direction_angles(shadow - camera.eye, camera.heading_deg, camera.pitch_deg);
        FlyFrameUniforms u;
        FlyFrameStats stats;
        flight.prepare(camera, u, stats, &aircraft);
        flight.renderer().render_to_memory(u, flight.patches(), with, &depth_with);
        const std::vector<blockers::Sphere> placed = flight.placed_aircraft_spheres();
        ASSERT_EQ(placed.size(), spheres.spheres.size());
        const glm::dvec3 bound_centre = glm::dvec3(u.aircraft_bound) + camera.eye;
        const double footprint = u.aircraft_shadow.y;
        flight.prepare(camera, u, stats, nullptr);
        flight.renderer().render_to_memory(u, flight.patches(), without, &depth_without);
        if (const char* dir = std::getenv("TS_TEST_PNG_DIR"))
            raster::write_png(std::string(dir) + "/fly_cessna_shadow_" + std::to_string(frame) + ".png", "shadow",
                              settings.width, settings.height, 4, with.data());
        const std::vector<glm::dvec3> points =
            terrain_points(u, camera.eye, depth_without, settings.width, settings.height, is_terrain);

        int umbra = 0, umbra_darker = 0, away = 0, away_changed = 0, brighter = 0, black = 0, terrain = 0;
        double umbra_drop = 0, height_error = 0;
        for (std::size_t i = 0; i < depth_without.size(); ++i) {
            if (!is_terrain[i]) continue;
            ++terrain;
            const std::uint8_t* a = &with[4 * i];
            const std::uint8_t* b = &without[4 * i];
            black += a[0] + a[1] + a[2] == 0;
            if (depth_with[i] != depth_without[i]) continue;  // the aircraft itself
            height_error = std::max(height_error, std::abs(points[i].z - flight.ground_height_m(points[i])));
            const double lum_with = (a[0] + a[1] + a[2]) / 3.0, lum_without = (b[0] + b[1] + b[2]) / 3.0;
            brighter += lum_with > lum_without + 0.5;
            const double left = sun_left(placed, points[i], sun);
            if (left < 0.05) {
                ++umbra;
                umbra_darker += lum_with < lum_without - 2.0;
                umbra_drop += lum_without - lum_with;
            } else if (left == 1.0 && glm::distance(points[i], bound_centre) > footprint) {
                ++away;
                away_changed += a[0] != b[0] || a[1] != b[1] || a[2] != b[2];
            }
        }
        std::printf("frame %d: %d terrain px, umbra %d px (%d darker, mean drop %.1f codes), %d px away (%d changed), "
                    "%d brighter, depth back to the ground within %.1f m\n",
                    frame, terrain, umbra, umbra_darker, umbra ? umbra_drop / umbra : 0.0, away, away_changed, brighter,
                    height_error);
        // The depth round trip lands on the drawn terrain (level 0 near the camera: bilinear
        // heights against the triangles of 157 x 222 m texels differ by a few metres).
        EXPECT_LT(height_error, 15.0);
        EXPECT_GT(umbra, 250) << "the predicted shadow is not in view";
        EXPECT_GE(umbra_darker, int(0.95 * umbra));
        EXPECT_GT(umbra_drop / std::max(umbra, 1), 20.0);
        EXPECT_GT(away, terrain / 10);
        EXPECT_EQ(away_changed, 0);
        EXPECT_EQ(brighter, 0);
        EXPECT_EQ(black, 0);
    }
}

// Exposed linear radiance behind an 8-bit display code (the inverse of display_shared.h's
// filmic curve and sRGB encoding, by bisection).
double exposed_of_code(int code) {
    double lo = 0.0, hi = 64.0;
    for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        (255.0 * raster::srgb_oetf(render::filmic(float(mid))) < code ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// A synthetic DEM at 45 N of 1/1200-degree texels: a valley running north-south, a flat floor
// five texels wide at 200 m about column 80 between walls at `wall_deg` (0: a plain).
dem::Dem valley_dem(double wall_deg) {
    dem::Dem dem;
    dem.width = 161, dem.height = 121;
    dem.z.resize(std::size_t(dem.width) * std::size_t(dem.height));
    dem.void_mask.assign(dem.z.size(), 0);
    const double pi = 3.14159265358979;
    const double dx = 6371008.8 * pi / 180.0 / 1200.0 * std::cos(45.0 * pi / 180.0);
    for (int r = 0; r < dem.height; ++r)
        for (int c = 0; c < dem.width; ++c)
            dem.z[dem.index(c, r)] = float(200.0 + std::tan(wall_deg * pi / 180.0) * std::max(std::abs(c - 80) - 4, 0) * dx);
    geo::GeoTransform t;
    t.x0 = 6.0, t.dx_col = 1.0 / 1200, t.y0 = 45.05, t.dy_row = -1.0 / 1200;
    dem.georef = geo::Georef(dem.width, dem.height, t, geo::Crs::wgs84(), true);
    return dem;
}

struct SkyShadowAtFloor {
    double drop = 0;         // the share of its light the floor under the aircraft loses
    double open_sky = 0;     // the floor texel's open-sky fraction
    double exact_cover = 0;  // the cosine-weighted sky the spheres' union hides there (rays), mean
    int pixels = 0;
};

// The Cessna (64 spheres) 9 m over the floor of valley_dem(wall_deg) under an overcast sky (the
// sky alone lights the floor), seen from 70 m south and 45 m up: the drop of the floor's pixels
// within 6 m of the point under it, read back through the display curve, against the frame
// without the aircraft.
SkyShadowAtFloor sky_shadow_at_floor(Context& context, double wall_deg, const mesh::TriangleMesh& cessna,
                                     const std::vector<blockers::Sphere>& spheres) {
    const dem::Dem dem = valley_dem(wall_deg);
    FlySettings settings;
    settings.width = 320;
    settings.height = 180;
    settings.directions = 16;
    settings.sky = "overcast";
    // Grey ground: the drop is read from the green channel alone (exposed_of_code), exact for a
    // grey; the hypsometric palette's green lowland put the ratio at 1.718.
    settings.colors.palette = *render::Palette::named("grey");
    // Sky light alone: the shadow takes its share of all the light besides the sun, so bounced
    // light from the walls (5% of the floor's here, which an aircraft overhead hardly blocks)
    // would put the ratio 0.09 higher.
    settings.bounce.bounces = 0;
    Flythrough flight(dem, settings, context);
    flight.set_time(light::parse_utc_time("2024-12-21T12:00:00Z"));
    flight.set_aircraft(cessna, 1.0, -90.0, spheres);
    const int low = (dem.height / 2) * dem.width + 80;
    const glm::dvec2 m = flight.frame().to_metric(low % dem.width, low / dem.width);
    const glm::dvec3 floor(m.x, m.y, flight.ground_height_m({m.x, m.y, 0}));
    SkyShadowAtFloor out;
    out.open_sky = flight.open_sky_fraction()[std::size_t(low)];

    fly::CameraPose aircraft;
    aircraft.eye = floor + glm::dvec3(0, 0, 9);
    fly::CameraPose camera;
    camera.eye = floor + glm::dvec3(0, -70, 45);
    fly::direction_angles(floor - camera.eye, camera.heading_deg, camera.pitch_deg);
    FlyFrameUniforms u;
    FlyFrameStats stats;
    std::vector<std::uint8_t> with, without;
    std::vector<float> depth_with, depth_without;
    flight.prepare(camera, u, stats, &aircraft);
    flight.renderer().render_to_memory(u, flight.patches(), with, &depth_with);
    const std::vector<blockers::Sphere> placed = flight.placed_aircraft_spheres();
    flight.prepare(camera, u, stats, nullptr);
    flight.renderer().render_to_memory(u, flight.patches(), without, &depth_without);
    if (const char* dir = std::getenv("TS_TEST_PNG_DIR"))
        raster::write_png(std::string(dir) + "/fly_cessna_sky_shadow_" + std::to_string(int(wall_deg)) + ".png",
                          "sky shadow", settings.width, settings.height, 4, with.data());
    std::vector<bool> is_terrain;
    const std::vector<glm::dvec3> points =
        terrain_points(u, camera.eye, depth_without, settings.width, settings.height, is_terrain);
    double sum_with = 0, sum_without = 0;
    std::vector<glm::dvec3> used;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!is_terrain[i] || depth_with[i] != depth_without[i]) continue;
        if (glm::length(glm::dvec2(points[i] - floor)) > 6.0) continue;
        sum_with += exposed_of_code(with[4 * i + 1]);
        sum_without += exposed_of_code(without[4 * i + 1]);
        used.push_back(points[i]);
        ++out.pixels;
    }
    out.drop = sum_without > 0 ? 1.0 - sum_with / sum_without : 0.0;
    // The exact cover over the same pixels (every 8th): cosine-distributed rays, 120 x 120 strata.
    auto exact_cover = [&placed](const glm::dvec3& from) {
        long hit = 0;
        const int n = 120;
        for (int a = 0; a < n; ++a)
            for (int b = 0; b < n; ++b) {
                const double u1 = (a + 0.5) / n, phi = 2 * 3.14159265358979 * (b + 0.5) / n;
                const glm::dvec3 dir(std::sqrt(u1) * std::cos(phi), std::sqrt(u1) * std::sin(phi), std::sqrt(1 - u1));
                for (const blockers::Sphere& sp : placed) {
                    const glm::dvec3 oc = sp.center - from;
                    const double t = glm::dot(oc, dir);
                    if (t > 0 && glm::dot(oc, oc) - t * t < sp.radius * sp.radius) {
                        ++hit;
                        break;
                    }
                }
            }
        return double(hit) / double(n * n);
    };
    double exact_sum = 0;
    int exact_n = 0;
    for (std::size_t k = 0; k < used.size(); k += 8, ++exact_n) exact_sum += exact_cover(used[k]);
    out.exact_cover = exact_n ? exact_sum / exact_n : 0.0;
    return out;
}

// The aircraft's sky shadow takes ts_open_sky_share of a texel's sky light, its cover over the
// texel's open-sky fraction: over a valley floor that sees less sky the same aircraft at the
// same height hides a larger share of it than over a plain, by the ratio of their open-sky
// fractions (the bare cover would give the same share). And over the plain its share is the
// cosine-weighted sky its spheres' union hides, within the union model's error.
TEST_F(FlyRenderTest, TheAircraftsSkyShadowInAValleyTakesItsCoverOverTheOpenSky) {
    const mesh::TriangleMesh cessna = mesh::import_mesh(std::string(TS_SHARED_DATA) + "/meshes/c172p.ac");
    blockers::DecompositionOptions d;
    d.count = 64;
    const blockers::SphereDecomposition spheres = blockers::decompose_into_spheres(cessna, d);
    const SkyShadowAtFloor plain = sky_shadow_at_floor(*context_, 0.0, cessna, spheres.spheres);
    const SkyShadowAtFloor valley = sky_shadow_at_floor(*context_, 55.0, cessna, spheres.spheres);
    for (const auto& [name, f] : {std::pair{"plain", plain}, std::pair{"valley", valley}})
        std::printf("%s: open-sky fraction %.3f, exact union cover %.4f, drop %.4f over %d px\n", name, f.open_sky,
                    f.exact_cover, f.drop, f.pixels);
    ASSERT_GT(plain.pixels, 10);
    ASSERT_GT(valley.pixels, 10);
    EXPECT_GT(plain.open_sky, 0.97);
    EXPECT_LT(valley.open_sky, 0.9);
    EXPECT_NEAR(valley.exact_cover, plain.exact_cover, 1e-3);  // the same aircraft over the same ground
    const double ratio = valley.drop / plain.drop, want = plain.open_sky / valley.open_sky;
    std::printf("valley / plain drop %.3f, open-sky ratio %.3f\n", ratio, want);
    // 8-bit codes: the pixels' rounding errors add up to a few percent of a drop of 0.1, and
    // where the floor's codes lie depends on the frame's exposure, so on the walls' colours: 1.656
    // with the guessed materials of earlier versions (dark forest walls), 1.686 on grey, 1.689 on
    // a darker grey (albedo 0.09). With the same share forced on both (an open-sky fraction of
    // 0.5 in the shader) the valley's drop reads 3.6% above the plain's; with the terrain's
    // transfer projected from its horizons (open-sky fraction 0.657 on the floor) the ratio is
    // 1.615 against 1.522 (with the log-SH transfer's 0.617: 1.618 against 1.619).
    EXPECT_NEAR(ratio, want, 0.12);
    EXPECT_GT(ratio, 1.0 + 0.75 * (want - 1.0));
    // The union of 64 overlapping spheres: caps combined as if scattered independently inside
    // the nodes the walk opens, the far ones by their share projected from below; +32% here.
    EXPECT_GT(plain.drop, plain.exact_cover);
    EXPECT_LT(plain.drop, 1.45 * plain.exact_cover);
}

// The aircraft's sky self-shadow on a closed form: the white plate (the aircraft) 300 m over
// the plain under an overcast sky, with one blocker sphere of radius 5 m 10 m above its centre
// (spheres need not bound the mesh), the plate in 1 m squares (the self-shadow is per vertex).
// Seen from above and to the south, the plate's pixels
// within 0.5 m of its centre keep 1 - sin^2(30 deg) = 0.75 of the light they have without the
// aircraft's shadows (the sky alone lights them); pixels 15 m out keep more.
TEST_F(FlyRenderTest, TheAircraftsOwnSpheresHideItsSky) {
    const dem::Dem dem = valley_dem(0.0);
    const std::vector<blockers::Sphere> sphere = {{{0.0, 0.0, 10.0}, 5.0}};
    std::vector<double> centre_ratio, edge_ratio;
    std::vector<std::vector<std::uint8_t>> frames;
    std::vector<std::vector<float>> depths;
    FlyFrameUniforms u;
    glm::dvec3 eye;
    for (const bool shadows : {true, false}) {
        FlySettings settings;
        settings.width = 320;
        settings.height = 180;
        settings.directions = 8;
        settings.sky = "overcast";
        settings.aircraft_shadows = shadows;
        Flythrough flight(dem, settings, *context_);
        flight.set_time(light::parse_utc_time("2024-12-21T12:00:00Z"));
        flight.set_aircraft(plate(40), 1.0, 0.0, sphere);
        const glm::dvec2 m = flight.frame().to_metric(80, 60);
        fly::CameraPose aircraft;
        aircraft.eye = glm::dvec3(m.x, m.y, flight.ground_height_m({m.x, m.y, 0}) + 300.0);
        fly::CameraPose camera;
        camera.eye = aircraft.eye + glm::dvec3(0, -20, 40);
        fly::direction_angles(aircraft.eye - camera.eye, camera.heading_deg, camera.pitch_deg);
        FlyFrameStats stats;
        std::vector<std::uint8_t> rgba;
        std::vector<float> depth;
        flight.prepare(camera, u, stats, &aircraft);
        flight.renderer().render_to_memory(u, flight.patches(), rgba, &depth);
        frames.push_back(rgba);
        depths.push_back(depth);
        eye = camera.eye;
        if (const char* dir = std::getenv("TS_TEST_PNG_DIR"))
            raster::write_png(std::string(dir) + "/fly_plate_sky_self_shadow_" + std::to_string(int(shadows)) + ".png",
                              "plate", settings.width, settings.height, 4, rgba.data());
    }
    // The plate's pixels (the same depth in both frames, 300 m over the ground) back in the
    // grid frame, relative to the plate's centre.
    std::vector<bool> hit;
    const std::vector<glm::dvec3> points = terrain_points(u, eye, depths[1], 320, 180, hit);
    const glm::dvec3 centre = eye + glm::dvec3(0, 20, -40);
    double with_c = 0, without_c = 0, with_e = 0, without_e = 0;
    int n_c = 0, n_e = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!hit[i] || depths[0][i] != depths[1][i] || std::abs(points[i].z - centre.z) > 0.5) continue;
        const double r = glm::length(glm::dvec2(points[i] - centre));
        const double a = exposed_of_code(frames[0][4 * i + 1]), b = exposed_of_code(frames[1][4 * i + 1]);
        if (r < 0.5) with_c += a, without_c += b, ++n_c;
        if (r > 14.0 && r < 16.0) with_e += a, without_e += b, ++n_e;
    }
    ASSERT_GT(n_c, 3) << "the plate's centre is not in view";
    ASSERT_GT(n_e, 10);
    const double centre_kept = with_c / without_c, edge_kept = with_e / without_e;
    // 15 m out the sphere's centre is 18 m away at 34 deg from the normal: sin^2 = (5/18)^2.
    const double edge_want = 1.0 - (5.0 / 18.03) * (5.0 / 18.03) * (10.0 / 18.03);
    std::printf("plate centre keeps %.3f of its light (want 0.750) over %d px; 15 m out %.3f (want %.3f) over %d px\n",
                centre_kept, n_c, edge_kept, edge_want, n_e);
    EXPECT_NEAR(centre_kept, 0.75, 0.02);
    EXPECT_NEAR(edge_kept, edge_want, 0.02);
}


// The sun's horizon from a point of the drawn surface (the level-0 heights, bilinear), marched
// towards the sun in grid coordinates (the grid's metric frame is linear over a march's length
// here) with the curvature drop: the tangent of the highest elevation, marched until it is
// settled against [tan_lo, tan_hi].
double sun_horizon_tangent(const dem::Dem& dem, const fly::GridFrame& frame, const glm::dvec3& p,
                           const glm::dvec3& sun, double tan_lo, double tan_hi, double z_max) {
    const glm::dvec2 dir = glm::normalize(glm::dvec2(sun));
    const glm::dvec2 g0 = frame.to_grid(p.x, p.y);
    const glm::dvec2 per_m = (frame.to_grid(p.x + 100.0 * dir.x, p.y + 100.0 * dir.y) - g0) / 100.0;
    auto height = [&](glm::dvec2 g) {
        const int c = std::min(int(g.x), dem.width - 2), r = std::min(int(g.y), dem.height - 2);
        const double fc = g.x - c, fr = g.y - r;
        const double top = dem.at(c, r) + fc * (dem.at(c + 1, r) - dem.at(c, r));
        const double bottom = dem.at(c, r + 1) + fc * (dem.at(c + 1, r + 1) - dem.at(c, r + 1));
        return top + fr * (bottom - top);
    };
    const double z0 = height(g0);
    double best = -1e9;
    for (double d = 5.0; d < 60000.0; d += d < 1000.0 ? 5.0 : 20.0) {
        // Settled: above the band, or nothing left high enough to reach it.
        if (best > tan_hi || (z_max - z0) / d < std::max(best, tan_lo)) break;
        const glm::dvec2 g = g0 + per_m * d;
        if (g.x < 0 || g.y < 0 || g.x > dem.width - 1 || g.y > dem.height - 1) break;
        best = std::max(best, (height(g) - z0 - d * d / (2.0 * 7321644.0)) / d);
    }
    return best;
}

// Close views over the SRTM tile N39E040 (90 m texels) with the sun 13 degrees up in the
// west-north-west, grey terrain, no haze: three frames 400 m above the ground looking down 25
// degrees north-north-east (the sun from the side).
struct ShadowViews {
    std::vector<std::vector<std::uint8_t>> rgba;
    std::vector<std::vector<float>> depth;
    std::vector<FlyFrameUniforms> frames;
    std::vector<glm::dvec3> eyes;
};

// `flight` gets the flight drawn, so its grid frame maps the pixels back to the grid.
ShadowViews draw_shadow_views(const dem::Dem& dem, Context& context, bool pixel_sun_shadows, const char* png,
                              std::unique_ptr<Flythrough>& flight) {
    FlySettings settings;
    settings.width = 480;
    settings.height = 270;
    settings.directions = 8;
    settings.colors.palette = *render::Palette::named("grey");
    settings.haze_km = 0.0;
    settings.pixel_sun_shadows = pixel_sun_shadows;
    flight = std::make_unique<Flythrough>(dem, settings, context);
    flight->set_time(light::parse_utc_time("2024-06-21T15:30:00Z"));
    ShadowViews views;
    const double centres[3][2] = {{40.15, 39.25}, {40.25, 39.40}, {40.35, 39.55}};
    for (int v = 0; v < 3; ++v) {
        const glm::dvec2 px = dem.georef.lonlat_to_pixel({centres[v][0], centres[v][1]});
        const glm::dvec2 m = flight->frame().to_metric(px.x - 0.5, px.y - 0.5);
        fly::CameraPose camera;
        camera.eye = glm::dvec3(m.x, m.y, 0.0);
        camera.eye.z = flight->ground_height_m(camera.eye) + 400.0;
        camera.heading_deg = 20.0;
        camera.pitch_deg = -25.0;
        FlyFrameUniforms u;
        FlyFrameStats stats;
        flight->prepare(camera, u, stats);
        views.rgba.emplace_back();
        views.depth.emplace_back();
        flight->renderer().render_to_memory(u, flight->patches(), views.rgba.back(), &views.depth.back());
        views.frames.push_back(u);
        views.eyes.push_back(camera.eye);
        if (const char* dir = std::getenv("TS_TEST_PNG_DIR"))
            raster::write_png(std::string(dir) + "/" + png + std::to_string(v) + ".png", "shadows", settings.width,
                              settings.height, 4, views.rgba.back().data());
    }
    return views;
}

struct ShadowClasses {
    int lit = 0, shaded = 0, wrong = 0;
    double lit_median = 0, shaded_median = 0;
};

// Close up, a shadow's edge is where the terrain casts it, not a texel-wide ramp: the fragments
// interpolate the texels' horizons in the sun's azimuth (--shadow-detail pixel) and shade the
// disc above them. The CPU marches towards the sun from each terrain pixel's point (its depth
// back to the grid) that faces the sun (n.s > 0.5) and finds it clearly lit (horizon 0.6 degree
// or more below the sun) or clearly shaded (as far above); counted: the pixels the frame draws
// on the wrong side of the midpoint between the two classes' median luminances. Under a third
// of those with the texels' visible shares blended (--shadow-detail texel, the flythrough's
// shading before): measured 48 against 249 of 14,429.
TEST_F(FlyRenderTest, CloseUpTheSunsShadowsFallWhereTheTerrainCastsThem) {
    const dem::Dem dem = dem::read_dem(std::string(TS_SHARED_DATA) + "/dem/srtm3_N39E040_1000px.tif");
    std::unique_ptr<Flythrough> flight;
    const ShadowViews texel_views = draw_shadow_views(dem, *context_, false, "fly_shadow_texel_", flight);
    const ShadowViews pixel_views = draw_shadow_views(dem, *context_, true, "fly_shadow_pixel_", flight);
    const fly::GridFrame* frame = &flight->frame();
    const glm::dvec3 sun = glm::normalize(glm::dvec3(pixel_views.frames[0].sun_direction));
    const double e = std::asin(sun.z), margin = 0.01;
    const double tan_lo = std::tan(e - margin), tan_hi = std::tan(e + margin);
    double z_max = -1e9;
    for (float z : dem.z) z_max = std::isnan(z) ? z_max : std::max(z_max, double(z));
    std::vector<std::pair<std::size_t, bool>> classed;  // (view * pixels + pixel, lit)
    const std::size_t n = pixel_views.depth[0].size();
    for (int v = 0; v < 3; ++v) {
        ASSERT_EQ(pixel_views.depth[std::size_t(v)], texel_views.depth[std::size_t(v)]);  // the same geometry
        std::vector<bool> is_terrain;
        const std::vector<glm::dvec3> points =
            terrain_points(pixel_views.frames[std::size_t(v)], pixel_views.eyes[std::size_t(v)],
                           pixel_views.depth[std::size_t(v)], 480, 270, is_terrain);
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (!is_terrain[i] || glm::distance(points[i], pixel_views.eyes[std::size_t(v)]) > 5000.0) continue;
            const glm::dvec3 p = points[i];
            auto z_at = [&](double dx, double dy) {
                const glm::dvec2 g = frame->to_grid(p.x + dx, p.y + dy);
                return double(dem.at(std::clamp(int(g.x + 0.5), 0, dem.width - 1), std::clamp(int(g.y + 0.5), 0, dem.height - 1)));
            };
            const glm::dvec3 normal = glm::normalize(glm::dvec3(-(z_at(90, 0) - z_at(-90, 0)) / 180.0,
                                                                -(z_at(0, 90) - z_at(0, -90)) / 180.0, 1.0));
            if (glm::dot(normal, sun) < 0.5) continue;
            const double t = sun_horizon_tangent(dem, *frame, p, sun, tan_lo, tan_hi, z_max);
            if (t > tan_lo && t < tan_hi) continue;
            classed.emplace_back(std::size_t(v) * n + i, t < tan_lo);
        }
    }
    auto classify = [&](const ShadowViews& views) {
        ShadowClasses c;
        std::vector<double> lit, shaded, lum(classed.size());
        for (std::size_t k = 0; k < classed.size(); ++k) {
            const std::uint8_t* px = &views.rgba[classed[k].first / n][4 * (classed[k].first % n)];
            lum[k] = (px[0] + px[1] + px[2]) / 3.0;
            (classed[k].second ? lit : shaded).push_back(lum[k]);
        }
        if (lit.empty() || shaded.empty()) return c;
        auto median = [](std::vector<double> v) {
            std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
            return v[v.size() / 2];
        };
        c.lit = int(lit.size()), c.shaded = int(shaded.size());
        c.lit_median = median(lit), c.shaded_median = median(shaded);
        const double mid = 0.5 * (c.lit_median + c.shaded_median);
        for (std::size_t k = 0; k < classed.size(); ++k) c.wrong += classed[k].second ? lum[k] < mid : lum[k] > mid;
        return c;
    };
    const ShadowClasses pixel = classify(pixel_views), texel = classify(texel_views);
    for (const auto& [name, c] : {std::pair{"pixel", pixel}, std::pair{"texel", texel}})
        std::printf("--shadow-detail %s: %d lit px (median %.1f), %d shaded (median %.1f), %d on the wrong side (%.2f%%)\n",
                    name, c.lit, c.lit_median, c.shaded, c.shaded_median, c.wrong,
                    100.0 * c.wrong / std::max(1, c.lit + c.shaded));
    ASSERT_GT(pixel.lit, 2000);
    ASSERT_GT(pixel.shaded, 1000);
    EXPECT_GT(pixel.lit_median, pixel.shaded_median + 30.0);
    EXPECT_LT(pixel.wrong, texel.wrong / 3);
}

}  // namespace
}  // namespace ts::gpu
