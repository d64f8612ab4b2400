// The detail tiles of a streamed DEM (core/fly/detail_tile*.hpp) on the Grenoble DEM: a tile's
// heights are the DEM's texels, neighbours agree on their shared edge, the cache keeps within its
// slots (evicting the least recently used tile no frame uses), hands each new or relit tile to
// the renderer once, and its worker thread brings requested tiles and stops with it.
#include "core/fly/detail_tile_cache.hpp"

#include <glm/geometric.hpp>
#include <glm/packing.hpp>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "core/dem/dem_source.hpp"
#include "core/dem/read_dem.hpp"
#include "core/fly/grid_frame.hpp"
#include "core/fly/terrain_overview.hpp"
#include "core/light/utc_time.hpp"
#include "core/render/render_scene.hpp"
#include "core/util/error.hpp"
#include "core/visibility/far_field_horizons.hpp"
#include "core/visibility/sun_disc_shared.hpp"
#include "core/visibility/sun_sweep.hpp"

namespace ts::fly {
namespace {

const std::string kGrenoble = std::string(TS_SHARED_DATA) + "/dem/copernicus_N45E005_grenoble_500px.tif";

// What a streamed flight keeps: the overview, the far field, the level-0 frame.
struct Streamed {
    dem::DemSource source{{kGrenoble}};
    TerrainOverview overview;
    std::unique_ptr<visibility::FarField> far;
    terrain::HeightGrid grid0;
    GridFrame frame;
    explicit Streamed(int level = 2) {
        visibility::FarFieldOptions fo;
        fo.start_texels = 32;
        TerrainOverviewOptions o;
        o.level = level;
        o.far_shift = visibility::FarField::coarse_shift_for(fo, source.layout().width, source.layout().height);
        overview = build_terrain_overview(source, o);
        terrain::HeightGrid coarse;
        coarse.width = overview.far_width, coarse.height = overview.far_height;
        coarse.z = overview.far_mean, coarse.dx_m = overview.far_dx_m, coarse.dy_m = overview.far_dy_m;
        far = std::make_unique<visibility::FarField>(coarse, overview.far_shift, overview.width, overview.height,
                                                     overview.dx0_m, overview.dy0_m, float(overview.z_top), fo);
        grid0.width = overview.width, grid0.height = overview.height;
        grid0.dx_m = overview.dx0_m, grid0.dy_m = overview.dy0_m;
        frame = GridFrame(grid0);
    }
    DetailCacheOptions options(int slots) const {
        DetailCacheOptions c;
        c.shading.halo = 32;
        c.shading.directions = 8;
        const std::size_t tile = detail_tile_bytes(256, 32);
        c.budget_bytes = tile * std::size_t(slots) + tile / 2;
        return c;
    }
};

struct Lit {
    double radiance;
    float open_sky, horizon;
};

render::SunState sun_of(const Streamed& s) {
    return render::sun_at(render::sun_site(s.overview.points), light::parse_utc_time("2024-06-21T16:00:00Z"));
}

TEST(DetailTile, HeightsAreTheDemsTexelsAndNeighboursShareTheirEdge) {
    Streamed s;
    const dem::Dem whole = dem::read_dem(kGrenoble);
    const DetailTileLayout layout = detail_tile_layout(s.overview, 16);
    ASSERT_EQ(layout.tiles_x, 2);
    DetailShadingOptions o;
    o.halo = 32;
    o.directions = 8;
    DetailTile west({0, 1}, layout, s.source, s.overview, *s.far, o);
    DetailTile east({1, 1}, layout, s.source, s.overview, *s.far, o);
    EXPECT_EQ(west.samples_x(), 257);
    EXPECT_EQ(east.samples_x(), s.overview.width - 256);  // the edge tile: up to the last texel
    for (int r = 0; r < west.samples_y(); r += 7)
        for (int c = 0; c < west.samples_x(); c += 5)
            ASSERT_EQ(west.heights()[std::size_t(r) * 257 + std::size_t(c)], whole.at(c, 256 + r));
    std::vector<std::uint32_t> lw, le, sw, se;
    const render::SunState sun = sun_of(s);
    west.light(sun, lw, sw);
    east.light(sun, le, se);
    ASSERT_EQ(lw.size(), 2 * west.heights().size());
    ASSERT_EQ(sw.size(), 4 * west.heights().size());
    // A sample's radiance at its centre as the fragments put it together (fly_terrain_frag.glsl).
    const glm::vec3 s_dir = glm::vec3(render::sun_direction(sun));
    const double radius = visibility::SunSweepOptions{}.sun_radius_rad;
    auto lit = [&](const std::vector<std::uint32_t>& l, const std::vector<std::uint32_t>& p, std::size_t i) {
        const glm::vec2 rg = glm::unpackHalf2x16(l[2 * i]), b0 = glm::unpackHalf2x16(l[2 * i + 1]);
        const glm::vec2 ar = glm::unpackHalf2x16(p[4 * i]), ab = glm::unpackHalf2x16(p[4 * i + 1]);
        const glm::vec2 en = glm::unpackHalf2x16(p[4 * i + 2]), h = glm::unpackHalf2x16(p[4 * i + 3]);
        const glm::vec3 n = glm::normalize(glm::vec3(en, std::sqrt(std::max(0.0f, 1.0f - glm::dot(en, en)))));
        const double f = visibility::shared::ts_sun_disc_fraction(-double(h.x) / radius);
        const double sun_term = (ar.x + ar.y + ab.x) * std::max(0.0f, glm::dot(n, s_dir)) * f;
        return Lit{rg.x + rg.y + b0.x + sun_term, ab.y, h.x};
    };
    // The shared column: the same heights; radiance from two windows within a few per cent.
    double worst = 0, worst_h = 0;
    for (int r = 0; r < west.samples_y(); ++r) {
        const std::size_t a = std::size_t(r) * std::size_t(west.samples_x()) + 256, b = std::size_t(r) * std::size_t(east.samples_x());
        ASSERT_EQ(west.heights()[a], east.heights()[b]);
        const Lit la = lit(lw, sw, a), lb = lit(le, se, b);
        ASSERT_GT(la.radiance, 0.0);
        worst = std::max(worst, std::abs(la.radiance - lb.radiance) / la.radiance);
        worst_h = std::max(worst_h, double(std::abs(la.horizon - lb.horizon)));
        ASSERT_GE(la.open_sky, 0.0f);
        ASSERT_LE(la.open_sky, 1.001f);
        ASSERT_GE(std::abs(la.horizon), 0.0f);
        ASSERT_LE(std::abs(la.horizon), float(visibility::kSunHorizonBandRad) * 1.001f);
    }
    std::printf("shared column: largest relative radiance difference %.4f, horizon %.5f rad\n", worst, worst_h);
    EXPECT_LT(worst, 0.02);
    EXPECT_LT(worst_h, 0.01);
}

TEST(DetailTileCache, KeepsWithinItsSlotsAndUploadsEachTileOnce) {
    Streamed s;
    DetailTileCache cache(s.source, s.overview, *s.far, s.frame, 16, s.options(4));
    ASSERT_EQ(cache.slots(), 4);
    cache.set_sun(sun_of(s));
    EXPECT_TRUE(cache.take_uploads().empty());
    // Frame 1 asks for three tiles (a level-1 node in each).
    const int per = 256 / (16 << 1);
    cache.request(1, 0, 0, 100.0);
    cache.request(1, per, 0, 200.0);
    cache.request(1, 0, per, 300.0);
    EXPECT_EQ(cache.load_requested_now(), 3);
    const std::vector<DetailSlotData> up = cache.take_uploads();
    ASSERT_EQ(up.size(), 3u);
    for (const DetailSlotData& d : up) {
        EXPECT_EQ(d.radiance.size(), 2 * d.heights->size());
        EXPECT_EQ(d.sun.size(), 2 * d.radiance.size());
    }
    EXPECT_TRUE(cache.take_uploads().empty());
    glm::vec2 z;
    EXPECT_TRUE(cache.node_z_range(0, 0, 0, z));
    EXPECT_LE(z.x, z.y);
    EXPECT_FALSE(cache.node_z_range(0, 16, 16, z));  // tile (1, 1) is not in
    EXPECT_NE(cache.slot_of_node(1, 0, 0), cache.slot_of_node(1, per, 0));
    cache.update({0, 0, 0});
    // Frame 2 uses tile (0, 0) and asks for (1, 1): the fourth slot.
    ASSERT_TRUE(cache.node_z_range(1, 0, 0, z));
    cache.request(1, per, per, 50.0);
    EXPECT_EQ(cache.load_requested_now(), 1);
    EXPECT_EQ(cache.resident(), 4u);
    EXPECT_LE(cache.peak_resident_bytes(), s.options(4).budget_bytes);
    // A new sun relights every resident tile, each listed once.
    cache.take_uploads();
    cache.set_sun(render::sun_at(render::sun_site(s.overview.points), light::parse_utc_time("2024-06-21T08:00:00Z")));
    EXPECT_EQ(cache.take_uploads().size(), 4u);
}

TEST(DetailTileCache, TheWorkerBringsRequestedTilesAndStopsWithTheCache) {
    Streamed s;
    auto cache = std::make_unique<DetailTileCache>(s.source, s.overview, *s.far, s.frame, 16, s.options(4));
    cache->set_sun(sun_of(s));
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (cache->resident() < 2 && std::chrono::steady_clock::now() < until) {
        cache->request(0, 0, 0, 10.0);
        cache->request(0, 17, 3, 20.0);  // tile (1, 0)
        cache->update({0, 0, 0});
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    EXPECT_EQ(cache->resident(), 2u);
    EXPECT_EQ(cache->take_uploads().size(), 2u);
    // Stopped while it may be building: the destructor joins it.
    cache->request(1, 8, 8, 5.0);
    cache->update({0, 0, 0});
    cache.reset();
}

TEST(DetailTileCache, ABudgetBelowFourTilesSaysWhatItNeeds) {
    Streamed s;
    try {
        DetailTileCache cache(s.source, s.overview, *s.far, s.frame, 16, s.options(2));
        FAIL() << "two tiles' budget accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("memory budget: "), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace ts::fly
