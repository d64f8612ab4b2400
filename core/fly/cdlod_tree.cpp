#include "core/fly/cdlod_tree.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/fly/cdlod_shared.hpp"

namespace ts::fly {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double height_at(const terrain::HeightGrid& g, int c, int r) { return double(g.at(c, r)); }

// Nearest distance from p to an axis-aligned box.
double box_distance(const glm::dvec3& p, const glm::dvec3& lo, const glm::dvec3& hi) {
    const glm::dvec3 q = glm::clamp(p, lo, hi);
    return glm::length(p - q);
}

}  // namespace

double mesh_error_m(const terrain::HeightGrid& g, int s, double quantile) {
    if (s <= 1) return 0.0;
    double worst = 0.0;
    std::vector<float> errors;
    if (quantile < 1.0) errors.reserve(std::size_t(g.width) * std::size_t(g.height));
    for (int r = 0; r < g.height; ++r) {
        const int r0 = (r / s) * s, r1 = std::min(r0 + s, g.height - 1);
        const double fr = r1 > r0 ? double(r - r0) / double(r1 - r0) : 0.0;
        for (int c = 0; c < g.width; ++c) {
            const int c0 = (c / s) * s, c1 = std::min(c0 + s, g.width - 1);
            const double fc = c1 > c0 ? double(c - c0) / double(c1 - c0) : 0.0;
            const double h00 = height_at(g, c0, r0), h10 = height_at(g, c1, r0);
            const double h01 = height_at(g, c0, r1), h11 = height_at(g, c1, r1);
            const double mesh = fc >= fr ? h00 + fc * (h10 - h00) + fr * (h11 - h10)
                                         : h00 + fr * (h01 - h00) + fc * (h11 - h01);
            const double e = std::abs(height_at(g, c, r) - mesh);
            if (e > worst) worst = e;
            if (quantile < 1.0) errors.push_back(float(e));
        }
    }
    if (quantile >= 1.0 || errors.empty()) return worst;
    const std::size_t rank = std::min(errors.size() - 1, std::size_t(quantile * double(errors.size())));
    std::nth_element(errors.begin(), errors.begin() + std::ptrdiff_t(rank), errors.end());
    return errors[rank];
}

bool box_in_frustum(const glm::dmat4& m, const glm::dvec3& lo, const glm::dvec3& hi) {
    glm::dvec4 clip[8];
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 p{(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
        clip[i] = m * glm::dvec4(p, 1.0);
    }
    // Vulkan clip volume -w <= x, y <= w, z <= w (nearer than the near plane is outside); the
    // projection is reversed-Z with an infinite far plane, so there is no far test.
    auto all_outside = [&](auto outside) {
        for (const auto& c : clip)
            if (!outside(c)) return false;
        return true;
    };
    if (all_outside([](const glm::dvec4& c) { return c.x < -c.w; })) return false;
    if (all_outside([](const glm::dvec4& c) { return c.x > c.w; })) return false;
    if (all_outside([](const glm::dvec4& c) { return c.y < -c.w; })) return false;
    if (all_outside([](const glm::dvec4& c) { return c.y > c.w; })) return false;
    if (all_outside([](const glm::dvec4& c) { return c.z > c.w; })) return false;
    return true;
}

CdlodTree::CdlodTree(const terrain::HeightGrid& g, const GridFrame& frame, const CdlodOptions& options)
    : frame_(frame), options_(options) {
    const int n = options_.patch_quads;
    if (n < 2 || (n & (n - 1)) != 0) throw std::invalid_argument("CdlodTree: patch_quads must be a power of two >= 2");
    if (g.width < 2 || g.height < 2) throw std::invalid_argument("CdlodTree: the grid needs at least 2x2 texels");
    const int extent = std::max(g.width - 1, g.height - 1);
    levels_ = 1;
    while (double(n) * double(1 << (levels_ - 1)) < double(extent)) ++levels_;

    if (!(options_.error_quantile >= 0.5 && options_.error_quantile <= 1.0))
        throw std::invalid_argument("CdlodTree: error_quantile must be in [0.5, 1]");
    error_m_.assign(std::size_t(levels_ + 1), 0.0);
    max_error_m_.assign(std::size_t(levels_ + 1), 0.0);
    for (int k = 1; k <= levels_; ++k) {
        max_error_m_[std::size_t(k)] = std::max(max_error_m_[std::size_t(k - 1)], mesh_error_m(g, 1 << k, 1.0));
        const double q = options_.error_quantile >= 1.0 ? max_error_m_[std::size_t(k)]
                                                         : mesh_error_m(g, 1 << k, options_.error_quantile);
        error_m_[std::size_t(k)] = std::max(error_m_[std::size_t(k - 1)], q);
    }

    boxes_.resize(std::size_t(levels_));
    diag_m_.assign(std::size_t(levels_), 0.0);
    for (int k = 0; k < levels_; ++k) {
        const double s = node_texels(k);
        nodes_x_.push_back(std::max(1, int(std::ceil(double(g.width - 1) / s))));
        nodes_y_.push_back(std::max(1, int(std::ceil(double(g.height - 1) / s))));
    }
    // Level 0 from the heights, every coarser level the union of its children.
    {
        const int nx = nodes_x(0), ny = nodes_y(0);
        auto& level0 = boxes_[0];
        level0.resize(std::size_t(nx) * std::size_t(ny));
        for (int iy = 0; iy < ny; ++iy) {
            const int r0 = iy * n, r1 = std::min(r0 + n, g.height - 1);
            for (int ix = 0; ix < nx; ++ix) {
                const int c0 = ix * n, c1 = std::min(c0 + n, g.width - 1);
                double zlo = kInfinity, zhi = -kInfinity;
                for (int r = r0; r <= r1; ++r)
                    for (int c = c0; c <= c1; ++c) {
                        const double z = height_at(g, c, r);
                        zlo = std::min(zlo, z), zhi = std::max(zhi, z);
                    }
                Box b;
                b.lo = glm::dvec3(kInfinity), b.hi = glm::dvec3(-kInfinity);
                for (int corner = 0; corner < 4; ++corner) {
                    const glm::dvec2 m = frame.to_metric((corner & 1) ? c1 : c0, (corner & 2) ? r1 : r0);
                    b.lo = glm::min(b.lo, glm::dvec3(m, zlo));
                    b.hi = glm::max(b.hi, glm::dvec3(m, zhi));
                }
                level0[std::size_t(iy) * std::size_t(nx) + std::size_t(ix)] = b;
            }
        }
    }
    for (int k = 1; k < levels_; ++k) {
        const int nx = nodes_x(k), ny = nodes_y(k);
        auto& level = boxes_[std::size_t(k)];
        level.resize(std::size_t(nx) * std::size_t(ny));
        for (int iy = 0; iy < ny; ++iy)
            for (int ix = 0; ix < nx; ++ix) {
                Box b;
                b.lo = glm::dvec3(kInfinity), b.hi = glm::dvec3(-kInfinity);
                for (int q = 0; q < 4; ++q) {
                    const int cx = 2 * ix + (q & 1), cy = 2 * iy + (q >> 1);
                    if (cx >= nodes_x(k - 1) || cy >= nodes_y(k - 1)) continue;
                    const Box& c = box(k - 1, cx, cy);
                    b.lo = glm::min(b.lo, c.lo), b.hi = glm::max(b.hi, c.hi);
                }
                level[std::size_t(iy) * std::size_t(nx) + std::size_t(ix)] = b;
            }
    }
    for (int k = 0; k < levels_; ++k)
        for (const Box& b : boxes_[std::size_t(k)])
            diag_m_[std::size_t(k)] = std::max(diag_m_[std::size_t(k)], glm::length(b.hi - b.lo));
}

const CdlodTree::Box& CdlodTree::box(int level, int ix, int iy) const {
    return boxes_[std::size_t(level)][std::size_t(iy) * std::size_t(nodes_x(level)) + std::size_t(ix)];
}

void CdlodTree::compute_ranges(double k_px, std::vector<double>& r) const {
    const double m = options_.morph_start_ratio, tau = options_.pixel_error;
    r.assign(std::size_t(levels_), kInfinity);
    for (int k = 0; k + 1 < levels_; ++k) {
        double v = error_m_[std::size_t(k + 1)] * k_px / (m * tau);
        if (k > 0) {
            v = std::max(v, 2.0 * r[std::size_t(k - 1)]);
            v = std::max(v, (r[std::size_t(k - 1)] + diag_m_[std::size_t(k - 1)]) / m);
        }
        r[std::size_t(k)] = v;
    }
}

double CdlodTree::range_m(int level, double k_px) const {
    std::vector<double> r;
    compute_ranges(k_px, r);
    return r[std::size_t(level)];
}

bool CdlodTree::select_node(int k, int ix, int iy, const CdlodView& view, const std::vector<double>& ranges,
                            double k_px, CdlodSelection& out) const {
    const Box& b = box(k, ix, iy);
    if (box_distance(view.eye, b.lo, b.hi) > ranges[std::size_t(k)]) return false;
    auto visible = [&](const Box& bb) {
        // The curvature lowers what is drawn: the box reaches down by the drop at its far corner.
        const glm::dvec2 far_xy = glm::max(glm::abs(glm::dvec2(bb.lo) - glm::dvec2(view.eye)),
                                           glm::abs(glm::dvec2(bb.hi) - glm::dvec2(view.eye)));
        const double drop = glm::dot(far_xy, far_xy) / (2.0 * TS_FLY_EFFECTIVE_EARTH_RADIUS_M);
        const glm::dvec3 lo = bb.lo - view.eye - glm::dvec3(0, 0, drop), hi = bb.hi - view.eye;
        return box_in_frustum(view.eye_relative_view_projection, lo, hi);
    };
    if (!visible(b)) return true;
    auto add = [&](int quadrant, const Box& bb) {
        CdlodPatch p;
        const double s = node_texels(k);
        p.col0 = float(ix * s), p.row0 = float(iy * s);
        p.spacing = float(1 << k);
        p.level = k;
        p.quadrant = quadrant;
        const double range = ranges[std::size_t(k)];
        const bool top = !std::isfinite(range);
        p.morph_end_m = top ? 1e30f : float(range);
        p.morph_start_m = top ? 1e30f : float(options_.morph_start_ratio * range);
        out.patches.push_back(p);
        out.triangles += quadrant < 0 ? triangles_per_patch() : triangles_per_patch() / 4;
        const double d = std::max(box_distance(view.eye, bb.lo, bb.hi), 1.0);
        auto bound = [&](const std::vector<double>& delta) {
            double e = delta[std::size_t(k)] * k_px / d;
            if (!top) e = std::max(e, delta[std::size_t(k + 1)] * k_px / std::max(d, double(p.morph_start_m)));
            return e;
        };
        out.screen_error_px = std::max(out.screen_error_px, bound(error_m_));
        out.screen_error_max_px = std::max(out.screen_error_max_px, bound(max_error_m_));
    };
    if (k == 0 || box_distance(view.eye, b.lo, b.hi) > ranges[std::size_t(k - 1)]) {
        add(-1, b);
        return true;
    }
    for (int q = 0; q < 4; ++q) {
        const int cx = 2 * ix + (q & 1), cy = 2 * iy + (q >> 1);
        if (cx >= nodes_x(k - 1) || cy >= nodes_y(k - 1)) continue;
        if (!select_node(k - 1, cx, cy, view, ranges, k_px, out)) {
            const Box& c = box(k - 1, cx, cy);
            if (visible(c)) add(q, c);
        }
    }
    return true;
}

void CdlodTree::select(const CdlodView& view, CdlodSelection& out) const {
    out.patches.clear();
    out.triangles = 0;
    out.screen_error_px = 0;
    out.screen_error_max_px = 0;
    const double k_px = view.viewport_height_px / (2.0 * std::tan(0.5 * view.vertical_fov_rad));
    std::vector<double> ranges;
    compute_ranges(k_px, ranges);
    const int top = levels_ - 1;
    for (int iy = 0; iy < nodes_y(top); ++iy)
        for (int ix = 0; ix < nodes_x(top); ++ix) select_node(top, ix, iy, view, ranges, k_px, out);
}

}  // namespace ts::fly
