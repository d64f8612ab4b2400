// The flythrough of a DEM streamed by tile (gpu/fly/flythrough.hpp's DemSource constructor), with
// the validation layer on: the frames of a short flight have terrain and sky and no crack where
// detail tiles, tile edges and the overview meet; they show what flying the DEM whole shows,
// within stated tolerances; the resident tiles stay within the budget's slots; a tight budget
// draws coarser instead of failing, and says so.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/dem/crop.hpp"
#include "core/dem/dem_source.hpp"
#include "core/dem/fill_voids.hpp"
#include "core/dem/read_dem.hpp"
#include "core/fly/flight_path.hpp"
#include "core/mesh/triangle_mesh.hpp"
#include "core/light/utc_time.hpp"
#include "core/raster/png_writer.hpp"
#include "core/util/error.hpp"
#include "gpu/fly/flythrough.hpp"
#include "tests/gpu/crack_pixels.hpp"
#include "tests/gpu/validated_context.hpp"

namespace ts::gpu {
namespace {

class FlyStreamTest : public test_support::ValidatedTest {};

const std::string kGrenoble = std::string(TS_SHARED_DATA) + "/dem/copernicus_N45E005_grenoble_500px.tif";

struct Frame {
    std::vector<std::uint8_t> rgba;
    std::vector<float> depth;
    FlyFrameStats stats;
};

fly::FlightPath low_path(const geo::Georef& g, int w, int h, double height_m) {
    const glm::dvec2 a = g.pixel_to_lonlat(0.30 * w, 0.70 * h);
    const glm::dvec2 b = g.pixel_to_lonlat(0.50 * w, 0.50 * h);
    return fly::FlightPath({{0, a.x, a.y, height_m, 45, -12, 0}, {10, b.x, b.y, height_m - 200, 60, -14, 0}});
}

std::vector<Frame> fly_path(Flythrough& flight, const fly::FlightPath& path, int frames, const char* name) {
    std::vector<Frame> out;
    for (int i = 0; i < frames; ++i) {
        Frame f;
        FlyFrameUniforms u;
        flight.prepare(flight.pose_of(path.at(10.0 * i / (frames - 1))), u, f.stats);
        flight.renderer().render_to_memory(u, flight.patches(), f.rgba, &f.depth);
        if (const char* dir = std::getenv("TS_TEST_PNG_DIR"))
            raster::write_png(std::string(dir) + "/" + name + std::to_string(i) + ".png", name, flight.renderer().width(),
                              flight.renderer().height(), 4, f.rgba.data());
        out.push_back(std::move(f));
    }
    return out;
}

FlySettings small_settings() {
    FlySettings s;
    s.width = 480, s.height = 270;
    s.directions = 8;
    s.wait_for_tiles = true;
    return s;
}

TEST_F(FlyStreamTest, AStreamedFlightShowsWhatTheWholeDemShowsWithoutCracks) {
    const dem::DemSource source({kGrenoble});
    dem::Dem whole = dem::read_dem(kGrenoble);
    dem::fill_voids(whole);
    FlySettings s = small_settings();
    s.overview_level = 2;
    s.memory_budget_bytes = std::size_t(1) << 30;
    s.detail_halo = 48;
    Flythrough streamed(source, s, *context_);
    ASSERT_TRUE(streamed.streamed());
    ASSERT_EQ(streamed.tree().stored_level(), 2);
    // The grid flown over: the DEM less its last (499 mod 4) columns and rows.
    EXPECT_EQ(streamed.frame().width(), 497);
    const dem::Dem cropped = dem::texel_window(whole, 0, 0, 497, 497);
    Flythrough reference(cropped, small_settings(), *context_);
    const light::UtcTime time = light::parse_utc_time("2024-06-21T08:00:00Z");
    streamed.set_time(time);
    reference.set_time(time);
    const fly::FlightPath path = low_path(source.layout().georef, whole.width, whole.height, 2300);
    const std::vector<Frame> a = fly_path(streamed, path, 4, "streamed_");
    const std::vector<Frame> b = fly_path(reference, path, 4, "whole_");
    const int w = s.width, h = s.height;
    for (std::size_t i = 0; i < a.size(); ++i) {
        SCOPED_TRACE("frame " + std::to_string(i));
        EXPECT_EQ(a[i].stats.coarse_fallbacks, 0u);
        EXPECT_GT(a[i].stats.tiles_resident, 0u);
        EXPECT_EQ(test_support::crack_pixels(a[i].depth, w, h, 0.2, 0.8), 0);
        EXPECT_LE(a[i].stats.screen_error_px, s.lod.pixel_error * 1.001);
        bool tile_patch = false;
        for (const auto& p : streamed.patches()) tile_patch = tile_patch || p.slot >= 0;
        EXPECT_TRUE(tile_patch);
        // Coverage agrees (the geometry), and the colours do, pixel by pixel where both see terrain.
        std::size_t both = 0, either = 0;
        double diff = 0;
        for (std::size_t k = 0; k < a[i].depth.size(); ++k) {
            const bool ta = a[i].depth[k] > 0, tb = b[i].depth[k] > 0;
            either += ta || tb, both += ta && tb;
            if (!(ta && tb)) continue;
            for (int c = 0; c < 3; ++c) diff += std::abs(int(a[i].rgba[4 * k + std::size_t(c)]) - int(b[i].rgba[4 * k + std::size_t(c)]));
        }
        ASSERT_GT(both, 0u);
        const double coverage = double(both) / double(either), mean_diff = diff / (3.0 * double(both));
        std::printf("frame %zu: coverage agreement %.4f, mean |display code difference| %.2f, %zu tiles\n", i, coverage,
                    mean_diff, a[i].stats.tiles_resident);
        EXPECT_GT(coverage, 0.995);
        EXPECT_LT(mean_diff, 5.0);
    }
    EXPECT_LE(streamed.detail_tiles()->resident(), std::size_t(streamed.detail_tiles()->slots()));
}

TEST_F(FlyStreamTest, ATightBudgetDrawsCoarserAndStaysInIt) {
    // 16 tiles of 256 texels; the budget holds a few.
    const dem::DemSource source({std::string(TS_SHARED_DATA) + "/dem/srtm3_N39E040_1000px.tif"});
    FlySettings s = small_settings();
    s.width = 960, s.height = 540;  // ranges twice as long: more tiles in view
    s.overview_level = 2;
    s.detail_halo = 32;
    s.memory_budget_bytes = std::size_t(130) << 20;
    Flythrough flight(source, s, *context_);
    flight.set_time(light::parse_utc_time("2024-06-21T08:00:00Z"));
    const int slots = flight.detail_tiles()->slots();
    ASSERT_GE(slots, 4);
    ASSERT_LT(slots, 8);
    const fly::FlightPath path = low_path(source.layout().georef, 1000, 1000, 3500);
    const std::vector<Frame> f = fly_path(flight, path, 3, "tight_");
    std::size_t fallbacks = 0;
    for (const Frame& x : f) {
        fallbacks += x.stats.coarse_fallbacks;
        EXPECT_LE(x.stats.tiles_resident, std::size_t(slots));
        std::size_t terrain = 0;
        for (float d : x.depth) terrain += d > 0;
        EXPECT_GT(double(terrain) / double(x.depth.size()), 0.3);
        std::printf("tight budget: %zu coarse fallbacks, %zu of %d slots, %zu tiles loaded, error bound %.2f px\n",
                    x.stats.coarse_fallbacks, x.stats.tiles_resident, slots, x.stats.tiles_loaded, x.stats.screen_error_px);
    }
    EXPECT_GT(fallbacks, 0u) << "four tiles cannot hold this view's detail: some nodes are drawn coarser";
    EXPECT_LE(flight.detail_tiles()->peak_resident_bytes(), s.memory_budget_bytes);
}

// A small plate: the aircraft whose terrain light is probed.
mesh::TriangleMesh probe_mesh() {
    mesh::TriangleMesh m;
    m.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}};
    m.normals.assign(3, glm::vec3(0, 0, 1));
    m.material = {0};
    m.materials = {mesh::MeshMaterial{"grey", glm::vec4(0.25f, 0.25f, 0.25f, 1.0f), ""}};
    return m;
}

// The aircraft's terrain light over a streamed DEM: the overview's horizons (every 8th texel
// here) raised by the level-0 tile under it, against the whole DEM's, 15 m over valley floors.
TEST_F(FlyStreamTest, TheAircraftsTerrainLightTakesTheTileUnderIt) {
    const dem::DemSource source({kGrenoble});
    dem::Dem whole = dem::read_dem(kGrenoble);
    dem::fill_voids(whole);
    FlySettings s = small_settings();
    s.overview_level = 3;
    s.memory_budget_bytes = std::size_t(1) << 30;
    Flythrough streamed(source, s, *context_);
    ASSERT_EQ(streamed.frame().width(), 497);
    const dem::Dem cropped = dem::texel_window(whole, 0, 0, 497, 497);
    Flythrough reference(cropped, small_settings(), *context_);
    const light::UtcTime time = light::parse_utc_time("2024-12-21T14:45:00Z");
    streamed.set_time(time);
    reference.set_time(time);
    streamed.set_aircraft(probe_mesh(), 1.0, 0.0);
    reference.set_aircraft(probe_mesh(), 1.0, 0.0);
    double worst_dc = 0, worst_sun = 0;
    int probes = 0, shaded = 0;
    for (int r = 120; r < 400; r += 40)
        for (int c = 120; c < 400; c += 40) {
            fly::CameraPose aircraft;
            const glm::dvec2 m = streamed.frame().to_metric(c, r);
            aircraft.eye = {m.x, m.y, double(cropped.at(c, r)) + 15.0};
            fly::CameraPose camera = aircraft;
            camera.eye += glm::dvec3(0, -60, 60);
            camera.pitch_deg = -45;
            FlyFrameUniforms u;
            FlyFrameStats st;
            streamed.prepare(camera, u, st, &aircraft);
            reference.prepare(camera, u, st, &aircraft);
            const render::PointTerrainLight a = streamed.aircraft_terrain_light(), b = reference.aircraft_terrain_light();
            const double dc_a = a.visible_sky[0].y, dc_b = b.visible_sky[0].y;
            worst_dc = std::max(worst_dc, std::abs(dc_a - dc_b) / dc_b);
            worst_sun = std::max(worst_sun, double(std::abs(a.sun_fraction - b.sun_fraction)));
            shaded += b.sun_fraction < 0.5;
            ++probes;
        }
    std::printf("%d probes (%d in the terrain's shadow): sky DC within %.4f relative, sun fraction within %.3f\n",
                probes, shaded, worst_dc, worst_sun);
    EXPECT_GT(shaded, 0);
    EXPECT_LT(worst_dc, 0.05);
    EXPECT_LT(worst_sun, 0.05);
}

TEST_F(FlyStreamTest, ABudgetBelowFourTilesIsAnInputError) {
    const dem::DemSource source({kGrenoble});
    FlySettings s = small_settings();
    s.overview_level = 2;
    s.memory_budget_bytes = std::size_t(20) << 20;
    EXPECT_THROW(Flythrough(source, s, *context_), InputError);
}

}  // namespace
}  // namespace ts::gpu
