// The CDLOD tree of a streamed DEM: coarse levels stored, finer ones answered by resident tiles
// (CdlodDetail). With every tile resident it selects what the tree of the DEM in memory selects;
// without some, it draws their parents whole, counts them and asks for the tiles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include "core/fly/cdlod_tree.hpp"
#include "core/fly/fly_camera.hpp"
#include "core/fly/grid_frame.hpp"
#include "core/terrain/height_grid.hpp"

namespace ts::fly {
namespace {

std::vector<float> ridges(int w, int h, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<float> z(std::size_t(w) * std::size_t(h));
    double fx[8], fy[8], ph[8], amp[8];
    for (int k = 0; k < 8; ++k)
        fx[k] = 0.003 + 0.12 * u(rng), fy[k] = 0.003 + 0.12 * u(rng), ph[k] = 6.28 * u(rng), amp[k] = 400.0 / (1 + k);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            double v = 1200.0;
            for (int k = 0; k < 8; ++k) v += amp[k] * std::abs(std::sin(fx[k] * c + fy[k] * r + ph[k]));
            z[std::size_t(r) * std::size_t(w) + std::size_t(c)] = float(v);
        }
    return z;
}

// Answers the finer levels from a whole summary, except the refused nodes' tiles.
class SummaryDetail final : public CdlodDetail {
public:
    SummaryDetail(const CdlodSummary& whole, int patch_quads, int tile_texels)
        : whole_(whole), n_(patch_quads), tile_(tile_texels) {}
    bool node_z_range(int level, int ix, int iy, glm::vec2& z) override {
        if (refused_.count(tile_of(level, ix, iy))) return false;
        const int nx = cdlod_node_count(whole_.width, whole_.height, n_, level).x;
        z = whole_.node_z[std::size_t(level)][std::size_t(iy) * std::size_t(nx) + std::size_t(ix)];
        return true;
    }
    void request(int level, int ix, int iy, double) override { requested_.insert(tile_of(level, ix, iy)); }
    std::pair<int, int> tile_of(int level, int ix, int iy) const {
        const int per = tile_ / (n_ << level);
        return {ix / per, iy / per};
    }
    std::set<std::pair<int, int>> refused_, requested_;

private:
    const CdlodSummary& whole_;
    int n_, tile_;
};

CdlodSummary streamed_summary(const CdlodSummary& whole, const GridFrame& frame, int patch_quads, int stored) {
    CdlodSummary s = whole;
    s.stored_level = stored;
    s.node_z.erase(s.node_z.begin(), s.node_z.begin() + stored);
    s.detail_diag_m.assign(std::size_t(stored), 0.0);
    for (int k = 0; k < stored; ++k) {
        const glm::ivec2 nodes = cdlod_node_count(whole.width, whole.height, patch_quads, k);
        for (int iy = 0; iy < nodes.y; ++iy)
            for (int ix = 0; ix < nodes.x; ++ix) {
                glm::dvec3 lo, hi;
                cdlod_node_box(frame, patch_quads, k, ix, iy,
                               whole.node_z[std::size_t(k)][std::size_t(iy) * std::size_t(nodes.x) + std::size_t(ix)], lo, hi);
                s.detail_diag_m[std::size_t(k)] = std::max(s.detail_diag_m[std::size_t(k)], glm::length(hi - lo));
            }
    }
    return s;
}

CdlodView view_over(const GridFrame& frame, glm::dvec3 eye, double heading, double pitch) {
    CameraPose pose;
    pose.eye = eye;
    pose.heading_deg = heading;
    pose.pitch_deg = pitch;
    Projection proj;
    proj.width = 960, proj.height = 540, proj.near_m = 5.0;
    CdlodView v;
    v.eye = eye;
    v.eye_relative_view_projection = eye_relative_view_projection(pose, proj);
    v.viewport_height_px = proj.height;
    v.vertical_fov_rad = proj.vertical_fov_rad();
    (void)frame;
    return v;
}

using PatchKey = std::tuple<float, float, int, int>;
std::vector<PatchKey> keys(const CdlodSelection& s) {
    std::vector<PatchKey> k;
    for (const CdlodPatch& p : s.patches) k.emplace_back(p.col0, p.row0, p.level, p.quadrant);
    std::sort(k.begin(), k.end());
    return k;
}

TEST(StreamedCdlod, WithEveryTileResidentItSelectsWhatTheWholeTreeSelects) {
    const int w = 1025, h = 769;
    const std::vector<float> z = ridges(w, h, 7);
    const terrain::HeightGrid g = terrain::HeightGrid::uniform(w, h, z, 30.0, 30.0);
    const GridFrame frame(g);
    CdlodOptions o;
    const CdlodSummary whole = summarize_cdlod(g, o);
    const CdlodTree reference(g, frame, o);
    for (int stored : {1, 2, 3}) {
        SummaryDetail detail(whole, o.patch_quads, 256);
        const CdlodTree tree(streamed_summary(whole, frame, o.patch_quads, stored), frame, o, &detail);
        ASSERT_EQ(tree.levels(), reference.levels());
        for (int k = 0; k < tree.levels(); ++k) {
            EXPECT_EQ(tree.range_m(k, 831.0), reference.range_m(k, 831.0)) << "stored " << stored << " level " << k;
        }
        int views = 0;
        for (double heading : {0.0, 77.0, 200.0})
            for (double height : {1700.0, 2600.0, 6000.0}) {
                const glm::dvec2 m = frame.to_metric(0.3 * w, 0.6 * h);
                const CdlodView v = view_over(frame, {m.x, m.y, height}, heading, -12.0);
                CdlodSelection a, b;
                reference.select(v, a);
                tree.select(v, b);
                EXPECT_EQ(b.coarse_fallbacks, 0u);
                EXPECT_EQ(keys(a), keys(b)) << "stored " << stored << " heading " << heading << " height " << height;
                EXPECT_EQ(a.screen_error_px, b.screen_error_px);
                ++views;
            }
        EXPECT_TRUE(detail.requested_.empty());
        EXPECT_EQ(views, 9);
    }
}

TEST(StreamedCdlod, AMissingTileDrawsItsNodesCoarserAndIsRequested) {
    const int w = 1025, h = 1025;
    const std::vector<float> z = ridges(w, h, 11);
    const terrain::HeightGrid g = terrain::HeightGrid::uniform(w, h, z, 30.0, 30.0);
    const GridFrame frame(g);
    CdlodOptions o;
    const CdlodSummary whole = summarize_cdlod(g, o);
    const int stored = 3;
    SummaryDetail detail(whole, o.patch_quads, 256);
    const CdlodTree tree(streamed_summary(whole, frame, o.patch_quads, stored), frame, o, &detail);
    // The eye low over tile (1, 1): its nodes want level 0 there.
    const glm::dvec2 m = frame.to_metric(384, 384);
    const CdlodView v = view_over(frame, {m.x, m.y, 2300.0}, 45.0, -30.0);
    CdlodSelection all;
    tree.select(v, all);
    ASSERT_EQ(all.coarse_fallbacks, 0u);
    bool fine_in_tile = false;
    for (const CdlodPatch& p : all.patches)
        fine_in_tile = fine_in_tile || (p.level < stored && int(p.col0) / 256 == 1 && int(p.row0) / 256 == 1);
    ASSERT_TRUE(fine_in_tile) << "the view should draw finer levels in tile (1, 1)";

    detail.refused_.insert({1, 1});
    CdlodSelection partial;
    tree.select(v, partial);
    EXPECT_GT(partial.coarse_fallbacks, 0u);
    EXPECT_TRUE(detail.requested_.count({1, 1}));
    for (const CdlodPatch& p : partial.patches)
        if (int(p.col0) / 256 == 1 && int(p.row0) / 256 == 1 && p.level < stored)
            ADD_FAILURE() << "a level-" << p.level << " patch in the missing tile";
    // Drawn coarser: the bound says so.
    EXPECT_GT(partial.screen_error_px, all.screen_error_px);
    // Elsewhere the selection is unchanged.
    auto outside = [&](const CdlodSelection& sel) {
        CdlodSelection kept;
        for (const CdlodPatch& p : sel.patches)
            if (!(int(p.col0) / 256 == 1 && int(p.row0) / 256 == 1)) kept.patches.push_back(p);
        return keys(kept);
    };
    EXPECT_EQ(outside(all), outside(partial));
}

TEST(StreamedCdlod, ASummaryForAnotherGridIsRefused) {
    const std::vector<float> z = ridges(129, 129, 3);
    const terrain::HeightGrid g = terrain::HeightGrid::uniform(129, 129, z, 30.0, 30.0);
    const GridFrame frame(g);
    CdlodSummary s = summarize_cdlod(g, {});
    s.error_m.pop_back();
    EXPECT_THROW(CdlodTree(s, frame, {}), std::invalid_argument);
    CdlodSummary t = summarize_cdlod(g, {});
    t.stored_level = 1;
    EXPECT_THROW(CdlodTree(t, frame, {}), std::invalid_argument);  // node_z and detail do not match
}

}  // namespace
}  // namespace ts::fly
