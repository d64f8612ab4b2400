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

int cdlod_level_count(int width, int height, int n) {
    const int extent = std::max(width - 1, height - 1);
    int levels = 1;
    while (double(n) * double(1 << (levels - 1)) < double(extent)) ++levels;
    return levels;
}

glm::ivec2 cdlod_node_count(int width, int height, int n, int level) {
    const double s = double(n) * double(1 << level);
    return {std::max(1, int(std::ceil(double(width - 1) / s))), std::max(1, int(std::ceil(double(height - 1) / s)))};
}

CdlodSummary summarize_cdlod(const terrain::HeightGrid& g, const CdlodOptions& options) {
    const int n = options.patch_quads;
    if (n < 2 || (n & (n - 1)) != 0) throw std::invalid_argument("CdlodTree: patch_quads must be a power of two >= 2");
    if (g.width < 2 || g.height < 2) throw std::invalid_argument("CdlodTree: the grid needs at least 2x2 texels");
    if (!(options.error_quantile >= 0.5 && options.error_quantile <= 1.0))
        throw std::invalid_argument("CdlodTree: error_quantile must be in [0.5, 1]");
    CdlodSummary s;
    s.width = g.width, s.height = g.height;
    const int levels = cdlod_level_count(g.width, g.height, n);
    s.error_m.assign(std::size_t(levels + 1), 0.0);
    s.max_error_m.assign(std::size_t(levels + 1), 0.0);
    for (int k = 1; k <= levels; ++k) {
        s.max_error_m[std::size_t(k)] = mesh_error_m(g, 1 << k, 1.0);
        s.error_m[std::size_t(k)] = options.error_quantile >= 1.0 ? s.max_error_m[std::size_t(k)]
                                                                  : mesh_error_m(g, 1 << k, options.error_quantile);
    }
    // Level 0 from the heights, every coarser level the union of its children.
    s.node_z.resize(std::size_t(levels));
    for (int k = 0; k < levels; ++k) {
        const glm::ivec2 nodes = cdlod_node_count(g.width, g.height, n, k);
        auto& level = s.node_z[std::size_t(k)];
        level.assign(std::size_t(nodes.x) * std::size_t(nodes.y), glm::vec2(float(kInfinity), -float(kInfinity)));
        for (int iy = 0; iy < nodes.y; ++iy)
            for (int ix = 0; ix < nodes.x; ++ix) {
                glm::vec2& z = level[std::size_t(iy) * std::size_t(nodes.x) + std::size_t(ix)];
                if (k == 0) {
                    const int r0 = iy * n, r1 = std::min(r0 + n, g.height - 1);
                    const int c0 = ix * n, c1 = std::min(c0 + n, g.width - 1);
                    for (int r = r0; r <= r1; ++r)
                        for (int c = c0; c <= c1; ++c) z.x = std::min(z.x, g.at(c, r)), z.y = std::max(z.y, g.at(c, r));
                    continue;
                }
                const glm::ivec2 below = cdlod_node_count(g.width, g.height, n, k - 1);
                for (int q = 0; q < 4; ++q) {
                    const int cx = 2 * ix + (q & 1), cy = 2 * iy + (q >> 1);
                    if (cx >= below.x || cy >= below.y) continue;
                    const glm::vec2 c = s.node_z[std::size_t(k - 1)][std::size_t(cy) * std::size_t(below.x) + std::size_t(cx)];
                    z.x = std::min(z.x, c.x), z.y = std::max(z.y, c.y);
                }
            }
    }
    return s;
}

CdlodTree::CdlodTree(const terrain::HeightGrid& g, const GridFrame& frame, const CdlodOptions& options)
    : frame_(frame), options_(options) {
    init(summarize_cdlod(g, options));
}

CdlodTree::CdlodTree(CdlodSummary summary, const GridFrame& frame, const CdlodOptions& options, CdlodDetail* detail)
    : frame_(frame), options_(options), detail_(detail) {
    init(std::move(summary));
}

void CdlodTree::init(CdlodSummary s) {
    const int n = options_.patch_quads;
    if (n < 2 || (n & (n - 1)) != 0) throw std::invalid_argument("CdlodTree: patch_quads must be a power of two >= 2");
    if (s.width < 2 || s.height < 2) throw std::invalid_argument("CdlodTree: the grid needs at least 2x2 texels");
    if (frame_.width() != s.width || frame_.height() != s.height)
        throw std::invalid_argument("CdlodTree: the frame is not the summary's grid");
    width_ = s.width, height_ = s.height;
    levels_ = cdlod_level_count(width_, height_, n);
    stored_level_ = std::clamp(s.stored_level, 0, levels_ - 1);
    if (s.error_m.size() != std::size_t(levels_ + 1) || s.max_error_m.size() != s.error_m.size() ||
        s.node_z.size() != std::size_t(levels_ - stored_level_) ||
        s.detail_diag_m.size() < std::size_t(stored_level_))
        throw std::invalid_argument("CdlodTree: the summary does not match the grid");
    if (stored_level_ > 0 && !detail_) throw std::invalid_argument("CdlodTree: levels below the stored ones need a detail");
    // Non-decreasing in k: a coarser mesh is never drawn nearer than a finer one.
    error_m_ = std::move(s.error_m), max_error_m_ = std::move(s.max_error_m);
    error_m_[0] = max_error_m_[0] = 0.0;
    for (int k = 1; k <= levels_; ++k) {
        max_error_m_[std::size_t(k)] = std::max(max_error_m_[std::size_t(k - 1)], max_error_m_[std::size_t(k)]);
        error_m_[std::size_t(k)] = std::max(error_m_[std::size_t(k - 1)], error_m_[std::size_t(k)]);
    }
    for (int k = 0; k < levels_; ++k) {
        const glm::ivec2 nodes = cdlod_node_count(width_, height_, n, k);
        nodes_x_.push_back(nodes.x), nodes_y_.push_back(nodes.y);
    }
    boxes_.resize(std::size_t(levels_ - stored_level_));
    diag_m_.assign(std::size_t(levels_), 0.0);
    for (int k = stored_level_; k < levels_; ++k) {
        const auto& z = s.node_z[std::size_t(k - stored_level_)];
        if (z.size() != std::size_t(nodes_x(k)) * std::size_t(nodes_y(k)))
            throw std::invalid_argument("CdlodTree: the summary's node count does not match the grid");
        auto& level = boxes_[std::size_t(k - stored_level_)];
        level.resize(z.size());
        for (int iy = 0; iy < nodes_y(k); ++iy)
            for (int ix = 0; ix < nodes_x(k); ++ix) {
                const std::size_t i = std::size_t(iy) * std::size_t(nodes_x(k)) + std::size_t(ix);
                level[i] = node_box_of(k, ix, iy, z[i]);
                diag_m_[std::size_t(k)] = std::max(diag_m_[std::size_t(k)], glm::length(level[i].hi - level[i].lo));
            }
    }
    for (int k = 0; k < stored_level_; ++k) diag_m_[std::size_t(k)] = s.detail_diag_m[std::size_t(k)];
}

void cdlod_node_box(const GridFrame& frame, int patch_quads, int k, int ix, int iy, glm::vec2 z, glm::dvec3& lo,
                    glm::dvec3& hi) {
    const int n = patch_quads << k;
    const int c0 = ix * n, c1 = std::min(c0 + n, frame.width() - 1);
    const int r0 = iy * n, r1 = std::min(r0 + n, frame.height() - 1);
    lo = glm::dvec3(kInfinity), hi = glm::dvec3(-kInfinity);
    for (int corner = 0; corner < 4; ++corner) {
        const glm::dvec2 m = frame.to_metric((corner & 1) ? c1 : c0, (corner & 2) ? r1 : r0);
        lo = glm::min(lo, glm::dvec3(m, double(z.x)));
        hi = glm::max(hi, glm::dvec3(m, double(z.y)));
    }
}

CdlodTree::Box CdlodTree::node_box_of(int k, int ix, int iy, glm::vec2 z) const {
    Box b;
    cdlod_node_box(frame_, options_.patch_quads, k, ix, iy, z, b.lo, b.hi);
    return b;
}

bool CdlodTree::node_box(int k, int ix, int iy, Box& out) const {
    if (k >= stored_level_) {
        out = boxes_[std::size_t(k - stored_level_)][std::size_t(iy) * std::size_t(nodes_x(k)) + std::size_t(ix)];
        return true;
    }
    glm::vec2 z;
    if (!detail_->node_z_range(k, ix, iy, z)) return false;
    out = node_box_of(k, ix, iy, z);
    return true;
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

bool CdlodTree::select_node(int k, int ix, int iy, const Box& b, const CdlodView& view,
                            const std::vector<double>& ranges, double k_px, CdlodSelection& out) const {
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
    Box children[4];
    bool exists[4];
    bool resident = true;
    for (int q = 0; q < 4; ++q) {
        const int cx = 2 * ix + (q & 1), cy = 2 * iy + (q >> 1);
        exists[q] = cx < nodes_x(k - 1) && cy < nodes_y(k - 1);
        if (exists[q] && !node_box(k - 1, cx, cy, children[q])) {
            resident = false;
            detail_->request(k - 1, cx, cy, box_distance(view.eye, b.lo, b.hi));
        }
    }
    if (!resident) {
        // Coarser than the range asks until the finer tile is in (the bound below says how much).
        ++out.coarse_fallbacks;
        add(-1, b);
        return true;
    }
    for (int q = 0; q < 4; ++q) {
        if (!exists[q]) continue;
        const int cx = 2 * ix + (q & 1), cy = 2 * iy + (q >> 1);
        if (!select_node(k - 1, cx, cy, children[q], view, ranges, k_px, out) && visible(children[q])) add(q, children[q]);
    }
    return true;
}

void CdlodTree::select(const CdlodView& view, CdlodSelection& out) const {
    out.patches.clear();
    out.triangles = 0;
    out.screen_error_px = 0;
    out.screen_error_max_px = 0;
    out.coarse_fallbacks = 0;
    const double k_px = view.viewport_height_px / (2.0 * std::tan(0.5 * view.vertical_fov_rad));
    std::vector<double> ranges;
    compute_ranges(k_px, ranges);
    const int top = levels_ - 1;
    for (int iy = 0; iy < nodes_y(top); ++iy)
        for (int ix = 0; ix < nodes_x(top); ++ix) {
            Box b;
            node_box(top, ix, iy, b);
            select_node(top, ix, iy, b, view, ranges, k_px, out);
        }
}

}  // namespace ts::fly
