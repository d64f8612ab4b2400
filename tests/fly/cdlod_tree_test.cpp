#include "core/fly/cdlod_tree.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/dem/dem.hpp"
#include "core/dem/read_dem.hpp"
#include "core/fly/cdlod_shared.hpp"
#include "core/fly/fly_camera.hpp"
#include "core/terrain/dem_height_grid.hpp"

namespace ts::fly {
namespace {

// A smooth random terrain: a sum of a few sines, 0..~1500 m.
std::vector<float> hills(int w, int h, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<float> z(std::size_t(w) * std::size_t(h));
    double fx[6], fy[6], ph[6], amp[6];
    for (int k = 0; k < 6; ++k)
        fx[k] = 0.002 + 0.05 * u(rng), fy[k] = 0.002 + 0.05 * u(rng), ph[k] = 6.28 * u(rng), amp[k] = 250.0 / (1 + k);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            double v = 700.0;
            for (int k = 0; k < 6; ++k) v += amp[k] * std::sin(fx[k] * c + fy[k] * r + ph[k]);
            z[std::size_t(r) * std::size_t(w) + std::size_t(c)] = float(v);
        }
    return z;
}

TEST(CdlodTree, MeshErrorOfAParabolaIsItsMidpointSag) {
    // z = a c^2 along columns: linear interpolation over s texels sags a s^2 / 4 at the midpoint.
    const int w = 65, h = 9;
    const double a = 0.5;
    std::vector<float> z(std::size_t(w) * h);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) z[std::size_t(r) * w + std::size_t(c)] = float(a * c * c);
    const terrain::HeightGrid g = terrain::HeightGrid::uniform(w, h, z, 30.0, 30.0);
    EXPECT_EQ(mesh_error_m(g, 1), 0.0);
    for (int s : {2, 4, 8, 16}) EXPECT_NEAR(mesh_error_m(g, s), a * s * s / 4.0, 1e-3) << "spacing " << s;
}

TEST(CdlodTree, ASpikeSetsTheMaximumButNotTheQuantile) {
    const int w = 65, h = 65;
    std::vector<float> z(std::size_t(w) * h, 500.0f);
    z[std::size_t(31) * w + 31] = 900.0f;  // one odd texel, 400 m above its neighbours
    const terrain::HeightGrid g = terrain::HeightGrid::uniform(w, h, z, 30.0, 30.0);
    EXPECT_NEAR(mesh_error_m(g, 2, 1.0), 400.0, 1e-3);
    EXPECT_NEAR(mesh_error_m(g, 2, 0.99), 0.0, 1e-3);
    const GridFrame f(g);
    const CdlodTree tree(g, f);
    EXPECT_NEAR(tree.level_max_error_m(1), 400.0, 1e-3);
    EXPECT_NEAR(tree.level_error_m(1), 0.0, 1e-3);
}

TEST(CdlodTree, PlaneHasNoErrorAtAnyLevel) {
    const int w = 129, h = 97;
    std::vector<float> z(std::size_t(w) * h);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) z[std::size_t(r) * w + std::size_t(c)] = float(100.0 + 2.0 * c - 3.0 * r);
    const terrain::HeightGrid g = terrain::HeightGrid::uniform(w, h, z, 30.0, 30.0);
    const GridFrame f(g);
    const CdlodTree tree(g, f);
    for (int k = 0; k <= tree.levels(); ++k) EXPECT_NEAR(tree.level_error_m(k), 0.0, 1e-3);
}

TEST(CdlodTree, RangesGrowAtLeastTwofoldAndMeetTheErrorGoal) {
    const int w = 513, h = 385;
    const std::vector<float> z = hills(w, h, 3);
    const terrain::HeightGrid g = terrain::HeightGrid::uniform(w, h, z, 30.0, 30.0);
    const GridFrame f(g);
    const CdlodTree tree(g, f);
    const double k_px = 540.0 / (2.0 * std::tan(0.3));
    for (int k = 1; k + 1 < tree.levels(); ++k) {
        EXPECT_GE(tree.range_m(k, k_px), 2.0 * tree.range_m(k - 1, k_px) - 1e-6);
        // From the morph start on, the next level's error projects to at most tau.
        const double start = tree.options().morph_start_ratio * tree.range_m(k, k_px);
        EXPECT_LE(tree.level_error_m(k + 1) * k_px / start, tree.options().pixel_error * (1 + 1e-9));
    }
    EXPECT_TRUE(std::isinf(tree.range_m(tree.levels() - 1, k_px)));
}

// --- No cracks: every edge two patches share has one shape on both sides. ---

struct Edge {
    double fixed = 0;      // the column (west/east) or row (north/south) of the edge
    double lo = 0, hi = 0; // its extent along the other axis
    bool vertical = true;  // along rows (west/east sides)
    std::vector<glm::dvec2> points;  // (coordinate along the edge, height) after the morph
};

struct Rect {
    double c0, r0, c1, r1;
};

struct Harness {
    const terrain::HeightGrid& g;
    const GridFrame& frame;
    int n;
    glm::dvec3 eye;

    double height(double c, double r) const {
        const int c0 = std::min(int(std::floor(c)), g.width - 2), r0 = std::min(int(std::floor(r)), g.height - 2);
        const double fc = c - c0, fr = r - r0;
        const double top = g.at(c0, r0) + fc * (g.at(c0 + 1, r0) - g.at(c0, r0));
        const double bottom = g.at(c0, r0 + 1) + fc * (g.at(c0 + 1, r0 + 1) - g.at(c0, r0 + 1));
        return top + fr * (bottom - top);
    }
    // What the vertex shader does with patch-grid index (i, j): texel position and height.
    glm::dvec3 vertex(const CdlodPatch& p, int i, int j) const {
        const double lc = g.width - 1, lr = g.height - 1;
        const double c = std::min(p.col0 + i * double(p.spacing), lc), r = std::min(p.row0 + j * double(p.spacing), lr);
        const glm::dvec2 m = frame.to_metric(c, r);
        const float d = float(glm::length(glm::dvec3(m, height(c, r)) - eye));
        const float k = shared::ts_cdlod_morph_factor(d, p.morph_start_m, p.morph_end_m);
        const double cm = std::min(p.col0 + shared::ts_cdlod_morph_index(float(i), k) * double(p.spacing), lc);
        const double rm = std::min(p.row0 + shared::ts_cdlod_morph_index(float(j), k) * double(p.spacing), lr);
        return {cm, rm, height(cm, rm)};
    }
    void index_range(const CdlodPatch& p, int& i0, int& i1, int& j0, int& j1) const {
        i0 = 0, i1 = n, j0 = 0, j1 = n;
        if (p.quadrant >= 0) {
            i0 = (p.quadrant & 1) * n / 2, i1 = i0 + n / 2;
            j0 = (p.quadrant >> 1) * n / 2, j1 = j0 + n / 2;
        }
    }
    Rect rect(const CdlodPatch& p) const {
        int i0, i1, j0, j1;
        index_range(p, i0, i1, j0, j1);
        const double lc = g.width - 1, lr = g.height - 1;
        return {std::min(p.col0 + i0 * double(p.spacing), lc), std::min(p.row0 + j0 * double(p.spacing), lr),
                std::min(p.col0 + i1 * double(p.spacing), lc), std::min(p.row0 + j1 * double(p.spacing), lr)};
    }
    // side: 0 west, 1 east, 2 north, 3 south
    Edge edge(const CdlodPatch& p, int side) const {
        int i0, i1, j0, j1;
        index_range(p, i0, i1, j0, j1);
        const Rect r = rect(p);
        Edge e;
        e.vertical = side < 2;
        e.fixed = side == 0 ? r.c0 : side == 1 ? r.c1 : side == 2 ? r.r0 : r.r1;
        e.lo = e.vertical ? r.r0 : r.c0;
        e.hi = e.vertical ? r.r1 : r.c1;
        for (int t = (e.vertical ? j0 : i0); t <= (e.vertical ? j1 : i1); ++t) {
            const int i = e.vertical ? (side == 0 ? i0 : i1) : t;
            const int j = e.vertical ? t : (side == 2 ? j0 : j1);
            const glm::dvec3 v = vertex(p, i, j);
            e.points.push_back({e.vertical ? v.y : v.x, v.z});
        }
        return e;
    }
};

// The height of an edge's polyline at coordinate s (its points are in increasing order).
double polyline_at(const Edge& e, double s) {
    for (std::size_t k = 1; k < e.points.size(); ++k) {
        const glm::dvec2 a = e.points[k - 1], b = e.points[k];
        if (s >= a.x - 1e-6 && s <= b.x + 1e-6) {
            if (b.x - a.x < 1e-9) return a.y;
            return a.y + (s - a.x) / (b.x - a.x) * (b.y - a.y);
        }
    }
    return std::nan("");
}

// Checks every pair of patches sharing an edge; returns the number of shared edges checked.
int check_no_cracks(const Harness& hs, const CdlodSelection& sel) {
    int shared_edges = 0;
    const auto& ps = sel.patches;
    for (std::size_t a = 0; a < ps.size(); ++a)
        for (std::size_t b = 0; b < ps.size(); ++b) {
            if (a == b) continue;
            const Rect ra = hs.rect(ps[a]), rb = hs.rect(ps[b]);
            // a's east side against b's west side, a's south side against b's north side.
            for (int dir = 0; dir < 2; ++dir) {
                const bool vertical = dir == 0;
                const double fa = vertical ? ra.c1 : ra.r1, fb = vertical ? rb.c0 : rb.r0;
                if (std::abs(fa - fb) > 1e-9) continue;
                const double lo = std::max(vertical ? ra.r0 : ra.c0, vertical ? rb.r0 : rb.c0);
                const double hi = std::min(vertical ? ra.r1 : ra.c1, vertical ? rb.r1 : rb.c1);
                if (hi - lo < 1e-9) continue;
                if (vertical ? (fa >= hs.g.width - 1) : (fa >= hs.g.height - 1)) continue;  // the DEM's border
                ++shared_edges;
                EXPECT_LE(std::abs(ps[a].level - ps[b].level), 1) << "neighbours more than one level apart";
                const Edge ea = hs.edge(ps[a], vertical ? 1 : 3), eb = hs.edge(ps[b], vertical ? 0 : 2);
                for (const Edge* e : {&ea, &eb}) {
                    const Edge& other = e == &ea ? eb : ea;
                    for (const glm::dvec2& p : e->points) {
                        if (p.x < lo - 1e-9 || p.x > hi + 1e-9) continue;
                        const double h_other = polyline_at(other, p.x);
                        EXPECT_FALSE(std::isnan(h_other)) << "edge point outside its neighbour's edge";
                        if (std::isnan(h_other)) continue;
                        EXPECT_NEAR(p.y, h_other, 1e-3) << "crack at " << (vertical ? "col " : "row ") << fa << ", "
                                                        << p.x << " between levels " << ps[a].level << " and "
                                                        << ps[b].level;
                    }
                }
            }
        }
    return shared_edges;
}

TEST(CdlodTree, SelectionOverHillsHasNoCracksAndMeetsTheErrorGoal) {
    const int w = 769, h = 641;
    const std::vector<float> z = hills(w, h, 11);
    const terrain::HeightGrid g = terrain::HeightGrid::uniform(w, h, z, 30.0, 30.0);
    const GridFrame f(g);
    const CdlodTree tree(g, f);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int edges = 0;
    std::vector<int> levels_seen(std::size_t(tree.levels()), 0);
    for (int view_index = 0; view_index < 12; ++view_index) {
        CameraPose pose;
        const glm::dvec2 m = f.to_metric((0.1 + 0.8 * u(rng)) * (w - 1), (0.1 + 0.8 * u(rng)) * (h - 1));
        pose.eye = {m.x, m.y, 1500.0 + 2000.0 * u(rng)};
        // Towards the grid's centre (metric origin), give or take 40 degrees: the DEM is in view.
        pose.heading_deg = std::atan2(-m.x, -m.y) * 180.0 / 3.14159265358979 + 80.0 * (u(rng) - 0.5);
        pose.pitch_deg = -5.0 - 40.0 * u(rng);
        Projection proj;
        CdlodView view;
        view.eye = pose.eye;
        view.eye_relative_view_projection = eye_relative_view_projection(pose, proj);
        view.viewport_height_px = proj.height;
        view.vertical_fov_rad = proj.vertical_fov_rad();
        CdlodSelection sel;
        tree.select(view, sel);
        ASSERT_FALSE(sel.patches.empty());
        EXPECT_LE(sel.screen_error_px, tree.options().pixel_error * (1 + 1e-5));  // morph starts are float
        EXPECT_EQ(sel.triangles % (tree.triangles_per_patch() / 4), 0u);
        for (const auto& p : sel.patches) ++levels_seen[std::size_t(p.level)];
        const Harness hs{g, f, tree.patch_quads(), pose.eye};
        edges += check_no_cracks(hs, sel);
    }
    EXPECT_GT(edges, 50);
    // More than one level is used, or the test proves nothing about transitions.
    EXPECT_GE(std::count_if(levels_seen.begin(), levels_seen.end(), [](int n) { return n > 0; }), 3);
}

TEST(CdlodTree, RealDemCropHasNoCracks) {
    const dem::Dem dem = dem::read_dem(std::string(TS_SHARED_DATA) + "/dem/copernicus_N45E005_grenoble_500px.tif");
    const terrain::HeightGrid g = terrain::metric_view(dem);
    const GridFrame f(g);
    const CdlodTree tree(g, f);
    CameraPose pose;
    const glm::dvec2 m = f.to_metric(100, 400);
    pose.eye = {m.x, m.y, 2500.0};
    pose.heading_deg = 45;
    pose.pitch_deg = -15;
    Projection proj;
    CdlodView view;
    view.eye = pose.eye;
    view.eye_relative_view_projection = eye_relative_view_projection(pose, proj);
    view.viewport_height_px = proj.height;
    view.vertical_fov_rad = proj.vertical_fov_rad();
    CdlodSelection sel;
    tree.select(view, sel);
    const Harness hs{g, f, tree.patch_quads(), pose.eye};
    EXPECT_GT(check_no_cracks(hs, sel), 10);
}

}  // namespace
}  // namespace ts::fly
