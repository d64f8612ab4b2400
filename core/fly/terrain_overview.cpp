#include "core/fly/terrain_overview.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/dem/fill_voids.hpp"
#include "core/fly/grid_frame.hpp"
#include "core/terrain/height_pyramid.hpp"
#include "core/util/error.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/progress_bar.hpp"
#include "core/visibility/far_field_horizons.hpp"

namespace ts::fly {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// |h - the level-k mesh| at texel (c, r) of a band whose first row is level-0 row `row0` (the
// mesh of cdlod_tree.cpp's mesh_error_m: samples every s texels, split along the quad's
// (0,0)-(1,1) diagonal); NaN where a height involved is a void.
double mesh_error_at(const std::vector<float>& band, int width, int row0, int height, int c, int r, int s) {
    auto at = [&](int cc, int rr) { return double(band[std::size_t(rr - row0) * std::size_t(width) + std::size_t(cc)]); };
    const int r0 = (r / s) * s, r1 = std::min(r0 + s, height - 1);
    const int c0 = (c / s) * s, c1 = std::min(c0 + s, width - 1);
    const double fr = r1 > r0 ? double(r - r0) / double(r1 - r0) : 0.0;
    const double fc = c1 > c0 ? double(c - c0) / double(c1 - c0) : 0.0;
    const double h00 = at(c0, r0), h10 = at(c1, r0), h01 = at(c0, r1), h11 = at(c1, r1);
    const double mesh = fc >= fr ? h00 + fc * (h10 - h00) + fr * (h11 - h10) : h00 + fr * (h01 - h00) + fc * (h11 - h01);
    return std::abs(at(c, r) - mesh);
}

}  // namespace

void ErrorHistogram::add(double e) {
    if (!(e >= 0.0)) return;
    int bin = 0;
    if (e > 1e-3) bin = 1 + int(std::floor(std::log2(e / 1e-3) * kBinsPerOctave));
    bins_[std::size_t(std::clamp(bin, 0, kBins - 1))] += 1;
    ++count_;
    max_ = std::max(max_, e);
}

void ErrorHistogram::merge(const ErrorHistogram& o) {
    for (std::size_t i = 0; i < bins_.size(); ++i) bins_[i] += o.bins_[i];
    count_ += o.count_;
    max_ = std::max(max_, o.max_);
}

double ErrorHistogram::quantile(double q) const {
    if (count_ == 0) return 0.0;
    if (q >= 1.0) return max_;
    // The rank mesh_error_m reads: floor(q n), 0-based.
    const std::uint64_t rank = std::min(count_ - 1, std::uint64_t(q * double(count_)));
    std::uint64_t seen = 0;
    for (int b = 0; b < kBins; ++b) {
        seen += bins_[std::size_t(b)];
        if (seen > rank) return b == 0 ? std::min(1e-3, max_) : std::min(max_, 1e-3 * std::exp2(double(b) / kBinsPerOctave));
    }
    return max_;
}

void row_spacing(const geo::Georef& georef, int width, int height, std::vector<double>& dx, std::vector<double>& dy) {
    dx.resize(std::size_t(height));
    dy.resize(std::size_t(height));
    for (int r = 0; r < height; ++r) {
        const glm::dvec2 cell = georef.cell_size_m(width * 0.5, r + 0.5);
        dx[std::size_t(r)] = cell.x, dy[std::size_t(r)] = cell.y;
    }
}

TerrainOverview build_terrain_overview(const dem::DemSource& source, const TerrainOverviewOptions& o,
                                       ProgressBar* progress) {
    const dem::DemLayout& layout = source.layout();
    if (o.level < 1 || o.level > 12) throw InputError("terrain overview: the level must be 1..12");
    const int step = 1 << o.level;
    TerrainOverview out;
    out.level = o.level;
    out.width = ((layout.width - 1) / step) * step + 1;
    out.height = ((layout.height - 1) / step) * step + 1;
    if (out.width < 2 * step + 1 || out.height < 2 * step + 1)
        throw input_error(layout.source, "too small to stream (" + std::to_string(layout.width) + "x" +
                                             std::to_string(layout.height) + " texels); fly it whole");
    const int W = out.width, H = out.height;
    const int pw = (W - 1) / step + 1, ph = (H - 1) / step + 1;
    row_spacing(layout.georef, W, H, out.dx0_m, out.dy0_m);
    const int n = o.lod.patch_quads;
    const int levels = cdlod_level_count(W, H, n);
    const int L = std::min(o.level, levels - 1);
    out.far_shift = std::max(0, o.far_shift);

    // Bands of level-L node rows, also a multiple of the far field's 2^far_shift rows.
    const int band = std::max(n << L, 1 << out.far_shift);
    std::vector<float> points(std::size_t(pw) * std::size_t(ph), std::numeric_limits<float>::quiet_NaN());
    std::vector<float> far_rows;
    const glm::ivec2 nodes_l = cdlod_node_count(W, H, n, L);
    std::vector<glm::vec2> node_z_l(std::size_t(nodes_l.x) * std::size_t(nodes_l.y), glm::vec2(kInf, -kInf));
    out.cdlod.detail_diag_m.assign(std::size_t(L), 0.0);
    terrain::HeightGrid spacing;
    spacing.width = W, spacing.height = H, spacing.dx_m = out.dx0_m, spacing.dy_m = out.dy0_m;
    const GridFrame frame(spacing);
    std::vector<ErrorHistogram> hist(std::size_t(L + 1));
    double z_top = -std::numeric_limits<double>::infinity();
    std::vector<float> z;
    const int workers = thread_count(o.threads);
    for (int row0 = 0; row0 < H - 1; row0 += band) {
        const int last = std::min(row0 + band, H - 1);  // inclusive: the next band's first row too
        const int rows = last - row0 + 1;
        source.read(0, row0, W, rows, z);
        // The band's own rows: its last is the next band's first, except at the end.
        const int own = last < H - 1 ? rows - 1 : rows;
        const auto own_end = z.begin() + std::ptrdiff_t(std::size_t(own) * std::size_t(W));
        out.void_texels += std::uint64_t(std::count_if(z.begin(), own_end, [](float v) { return std::isnan(v); }));
        for (float v : z)
            if (v == v) z_top = std::max(z_top, double(v));
        // The points on this band's rows (its last row is the next band's first, except at the end).
        for (int r = row0; r <= last; r += step) {
            if (r == last && last < H - 1) break;
            float* to = points.data() + std::size_t(r / step) * std::size_t(pw);
            const float* from = z.data() + std::size_t(r - row0) * std::size_t(W);
            for (int c = 0; c < W; c += step) to[c / step] = from[c];
        }
        // The far field's mean level over the band's own rows.
        {
            std::vector<float> m(z.begin(), own_end);
            int w = W, h = own;
            for (int k = 0; k < out.far_shift; ++k) {
                m = terrain::downsample_2x2(m.data(), w, h, false, 1);
                w = (w + 1) / 2, h = (h + 1) / 2;
            }
            far_rows.insert(far_rows.end(), m.begin(), m.end());
            out.far_width = w;
            out.far_height += h;
        }
        // Node height ranges: level 0 from the texels, up to level L by union.
        std::vector<std::vector<glm::vec2>> nz(std::size_t(L + 1));
        std::vector<int> nx(std::size_t(L + 1)), ny(std::size_t(L + 1));
        for (int k = 0; k <= L; ++k) {
            nx[std::size_t(k)] = cdlod_node_count(W, H, n, k).x;
            ny[std::size_t(k)] = std::max(1, (rows - 1 + (n << k) - 1) / (n << k));
            nz[std::size_t(k)].assign(std::size_t(nx[std::size_t(k)]) * std::size_t(ny[std::size_t(k)]), glm::vec2(kInf, -kInf));
        }
        parallel_for(ny[0], workers, [&](int iy, int) {
            const int r0 = iy * n, r1 = std::min(r0 + n, rows - 1);
            for (int ix = 0; ix < nx[0]; ++ix) {
                glm::vec2& b = nz[0][std::size_t(iy) * std::size_t(nx[0]) + std::size_t(ix)];
                const int c0 = ix * n, c1 = std::min(c0 + n, W - 1);
                for (int r = r0; r <= r1; ++r)
                    for (int c = c0; c <= c1; ++c) {
                        const float v = z[std::size_t(r) * std::size_t(W) + std::size_t(c)];
                        if (v == v) b.x = std::min(b.x, v), b.y = std::max(b.y, v);
                    }
            }
        });
        for (int k = 1; k <= L; ++k)
            for (int iy = 0; iy < ny[std::size_t(k)]; ++iy)
                for (int ix = 0; ix < nx[std::size_t(k)]; ++ix) {
                    glm::vec2& b = nz[std::size_t(k)][std::size_t(iy) * std::size_t(nx[std::size_t(k)]) + std::size_t(ix)];
                    for (int q = 0; q < 4; ++q) {
                        const int cx = 2 * ix + (q & 1), cy = 2 * iy + (q >> 1);
                        if (cx >= nx[std::size_t(k - 1)] || cy >= ny[std::size_t(k - 1)]) continue;
                        const glm::vec2 c = nz[std::size_t(k - 1)][std::size_t(cy) * std::size_t(nx[std::size_t(k - 1)]) + std::size_t(cx)];
                        b.x = std::min(b.x, c.x), b.y = std::max(b.y, c.y);
                    }
                }
        // The finer levels' largest node diagonal, as the tree measures its stored boxes.
        for (int k = 0; k < L; ++k) {
            const int first = row0 / (n << k);
            for (int iy = 0; iy < ny[std::size_t(k)]; ++iy)
                for (int ix = 0; ix < nx[std::size_t(k)]; ++ix) {
                    const glm::vec2 b = nz[std::size_t(k)][std::size_t(iy) * std::size_t(nx[std::size_t(k)]) + std::size_t(ix)];
                    if (!(b.y >= b.x)) continue;
                    glm::dvec3 lo, hi;
                    cdlod_node_box(frame, n, k, ix, first + iy, b, lo, hi);
                    out.cdlod.detail_diag_m[std::size_t(k)] = std::max(out.cdlod.detail_diag_m[std::size_t(k)], glm::length(hi - lo));
                }
        }
        const int first_node_row = row0 / (n << L);
        for (int iy = 0; iy < ny[std::size_t(L)] && first_node_row + iy < nodes_l.y; ++iy)
            for (int ix = 0; ix < nx[std::size_t(L)]; ++ix)
                node_z_l[std::size_t(first_node_row + iy) * std::size_t(nodes_l.x) + std::size_t(ix)] =
                    nz[std::size_t(L)][std::size_t(iy) * std::size_t(nx[std::size_t(L)]) + std::size_t(ix)];
        // Mesh errors of levels 1..L over the band's own rows.
        std::vector<std::vector<ErrorHistogram>> local(std::size_t(workers), std::vector<ErrorHistogram>(std::size_t(L + 1)));
        parallel_for(own, workers, [&](int i, int worker) {
            const int r = row0 + i;
            for (int k = 1; k <= L; ++k)
                for (int c = 0; c < W; ++c) {
                    const double e = mesh_error_at(z, W, row0, H, c, r, 1 << k);
                    if (e == e) local[std::size_t(worker)][std::size_t(k)].add(e);
                }
        });
        for (const auto& l : local)
            for (int k = 1; k <= L; ++k) hist[std::size_t(k)].merge(l[std::size_t(k)]);
        if (progress) progress->advance(std::uint64_t(own) * std::uint64_t(W));
    }
    if (!std::isfinite(z_top)) throw input_error(layout.source, "has no valid height");
    out.z_top = z_top;

    // The points as a DEM: sample (i, j) is level-0 texel (i, j) 2^level, so its cell is centred there.
    out.points.width = pw, out.points.height = ph;
    out.points.z = std::move(points);
    out.points.void_mask.resize(out.points.z.size());
    for (std::size_t i = 0; i < out.points.z.size(); ++i) out.points.void_mask[i] = std::isnan(out.points.z[i]) ? 1 : 0;
    geo::GeoTransform t = layout.georef.transform();
    const double s = double(step), shift = 0.5 - 0.5 * s;
    const glm::dvec2 origin = t.apply(shift, shift);
    t.x0 = origin.x, t.y0 = origin.y;
    t.dx_col *= s, t.dy_col *= s, t.dx_row *= s, t.dy_row *= s;
    out.points.georef = geo::Georef(pw, ph, t, layout.georef.crs_ptr(), layout.georef.pixel_is_area());
    out.points.vertical_datum = layout.vertical_datum;
    out.points.source = layout.source;
    dem::fill_voids(out.points);
    // What stays NaN is outside the terrain (a reprojection's collar, a hole too wide to fill):
    // the mesh needs a height, so it is drawn as a flat floor at the lowest height (docs/terrain.md).
    dem::floor_outside(out.points);

    out.far_mean = std::move(far_rows);
    // The level's row spacing as the far field's coarse copy sums it.
    out.far_dx_m = out.dx0_m, out.far_dy_m = out.dy0_m;
    for (int k = 0; k < out.far_shift; ++k) visibility::halve_row_spacing(out.far_dx_m, out.far_dy_m);

    // The summary: errors up to L from the histograms, beyond from the points (the level-k mesh
    // against the level-0 texels the points keep); node ranges from L up.
    CdlodSummary& cs = out.cdlod;
    cs.width = W, cs.height = H;
    cs.stored_level = L;
    cs.error_m.assign(std::size_t(levels + 1), 0.0);
    cs.max_error_m.assign(std::size_t(levels + 1), 0.0);
    for (int k = 1; k <= L; ++k) {
        cs.error_m[std::size_t(k)] = hist[std::size_t(k)].quantile(o.lod.error_quantile);
        cs.max_error_m[std::size_t(k)] = hist[std::size_t(k)].max();
    }
    std::vector<double> pdx, pdy;
    row_spacing(out.points.georef, pw, ph, pdx, pdy);
    terrain::HeightGrid pg;
    pg.width = pw, pg.height = ph, pg.z = out.points.z, pg.dx_m = pdx, pg.dy_m = pdy;
    for (int k = L + 1; k <= levels; ++k) {
        cs.max_error_m[std::size_t(k)] = mesh_error_m(pg, 1 << (k - L), 1.0);
        cs.error_m[std::size_t(k)] = o.lod.error_quantile >= 1.0 ? cs.max_error_m[std::size_t(k)]
                                                                 : mesh_error_m(pg, 1 << (k - L), o.lod.error_quantile);
    }
    // A node with no valid height takes the filled points' range inside it.
    for (int iy = 0; iy < nodes_l.y; ++iy)
        for (int ix = 0; ix < nodes_l.x; ++ix) {
            glm::vec2& b = node_z_l[std::size_t(iy) * std::size_t(nodes_l.x) + std::size_t(ix)];
            if (b.y >= b.x) continue;
            const int per = n;  // points per node side at level L
            for (int j = iy * per; j <= std::min((iy + 1) * per, ph - 1); ++j)
                for (int i = ix * per; i <= std::min((ix + 1) * per, pw - 1); ++i) {
                    const float v = out.points.at(i, j);
                    b.x = std::min(b.x, v), b.y = std::max(b.y, v);
                }
        }
    cs.node_z.clear();
    cs.node_z.push_back(std::move(node_z_l));
    for (int k = L + 1; k < levels; ++k) {
        const glm::ivec2 nodes = cdlod_node_count(W, H, n, k), below = cdlod_node_count(W, H, n, k - 1);
        std::vector<glm::vec2> level(std::size_t(nodes.x) * std::size_t(nodes.y), glm::vec2(kInf, -kInf));
        const auto& prev = cs.node_z.back();
        for (int iy = 0; iy < nodes.y; ++iy)
            for (int ix = 0; ix < nodes.x; ++ix)
                for (int q = 0; q < 4; ++q) {
                    const int cx = 2 * ix + (q & 1), cy = 2 * iy + (q >> 1);
                    if (cx >= below.x || cy >= below.y) continue;
                    const glm::vec2 c = prev[std::size_t(cy) * std::size_t(below.x) + std::size_t(cx)];
                    glm::vec2& b = level[std::size_t(iy) * std::size_t(nodes.x) + std::size_t(ix)];
                    b.x = std::min(b.x, c.x), b.y = std::max(b.y, c.y);
                }
        cs.node_z.push_back(std::move(level));
    }
    if (progress) progress->finish();
    return out;
}

}  // namespace ts::fly
