#include "core/render/surface_march.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/terrain/height_pyramid.hpp"
#include "core/terrain/smooth_surface.hpp"
#include "core/util/parallel_for.hpp"
#include "core/visibility/sun_visibility.hpp"

namespace ts::render {

double SurfaceRay::min_height(double s0, double s1) const {
    double m = std::min(height_at(s0), height_at(s1));
    if (curv > 0) {
        const double sv = -kz / (2 * curv);
        if (sv > s0 && sv < s1) m = std::min(m, height_at(sv));
    }
    return m;
}

SurfaceMarch::SurfaceMarch(const terrain::HeightGrid& g, int threads) : grid_(g) {
    const int pw = std::max(1, g.width - 1), ph = std::max(1, g.height - 1);
    std::vector<float> level0(std::size_t(pw) * ph);
    parallel_rows(ph, threads, pw * 40LL, [&](int j0, int j1) {
        for (int j = j0; j < j1; ++j)
            for (int i = 0; i < pw; ++i) level0[std::size_t(j) * pw + i] = terrain::smooth_patch_bound(g, i, j);
    });
    max_.push_back(std::move(level0));
    w_.push_back(pw), h_.push_back(ph);
    while (w_.back() > 1 || h_.back() > 1) {
        max_.push_back(terrain::downsample_2x2(max_.back().data(), w_.back(), h_.back(), true, threads));
        w_.push_back((w_.back() + 1) / 2), h_.push_back((h_.back() + 1) / 2);
    }
}

SurfaceMarch::Cell SurfaceMarch::cell_at(const SurfaceRay& ray, int level, double s, double s_end) const {
    const double x = ray.x0 + s * ray.ux, y = ray.y0 + s * ray.uy;
    const int size = 1 << level;
    const int ci = std::clamp(int(std::floor(x / size)), 0, w_[std::size_t(level)] - 1);
    const int cj = std::clamp(int(std::floor(y / size)), 0, h_[std::size_t(level)] - 1);
    double exit = s_end;
    if (ray.ux > 0) exit = std::min(exit, ((ci + 1.0) * size - ray.x0) / ray.ux);
    if (ray.ux < 0) exit = std::min(exit, (double(ci) * size - ray.x0) / ray.ux);
    if (ray.uy > 0) exit = std::min(exit, ((cj + 1.0) * size - ray.y0) / ray.uy);
    if (ray.uy < 0) exit = std::min(exit, (double(cj) * size - ray.y0) / ray.uy);
    return {max_[std::size_t(level)][std::size_t(cj) * w_[std::size_t(level)] + ci], std::max(exit, s)};
}

template <class Patch>
void SurfaceMarch::walk(const SurfaceRay& ray, double s_begin, double s_end, double nudge, Patch&& patch) const {
    const int top = int(max_.size()) - 1;
    int level = top;
    double s = s_begin;
    for (int guard = 0; guard < 1 << 22 && s <= s_end; ++guard) {
        const Cell cell = cell_at(ray, level, s, s_end);
        if (ray.min_height(s, cell.exit) > double(cell.bound)) {
            s = cell.exit + nudge;
            level = std::min(level + 1, top);
            continue;
        }
        if (level > 0) {
            --level;
            continue;
        }
        if (patch(s, cell.exit)) return;
        s = cell.exit + nudge;
        level = std::min(1, top);
    }
}

double SurfaceMarch::first_hit(const SurfaceRay& ray, double s_begin, double s_end, double nudge) const {
    auto below = [&](double t) {
        const float h = terrain::smooth_surface(grid_, ray.x0 + t * ray.ux, ray.y0 + t * ray.uy).z;
        return !std::isnan(h) && ray.height_at(t) <= double(h);
    };
    double hit = -1.0;
    // A patch the ray may cross: bracket by sub-steps, refine by bisection.
    walk(ray, s_begin, s_end, nudge, [&](double s, double exit) {
        constexpr int kSteps = 4;
        if (below(s)) return hit = s, true;
        double prev = s;
        for (int k = 1; k <= kSteps; ++k) {
            const double t = s + (exit - s) * k / kSteps;
            if (below(t)) {
                double lo = prev, hi = t;
                for (int it = 0; it < 12; ++it) {
                    const double mid = 0.5 * (lo + hi);
                    (below(mid) ? hi : lo) = mid;
                }
                hit = hi;
                return true;
            }
            prev = t;
        }
        return false;
    });
    return hit;
}

double SurfaceMarch::horizon_tangent(const SurfaceRay& ray_in, double s_begin, double s_end, double floor_tan,
                                     double ceiling_tan, double nudge) const {
    // The line at the best tangent so far (with the Earth's drop as its lift): a cell entirely
    // below it cannot raise the horizon.
    SurfaceRay ray = ray_in;
    ray.kz = floor_tan;
    double last_sample = -1;
    walk(ray, s_begin, s_end, nudge, [&](double s, double exit) {
        constexpr int kSteps = 4;
        for (int k = 0; k <= kSteps; ++k) {
            const double t = s + (exit - s) * k / kSteps;
            // The previous patch's last sample stands for this one's first.
            if (t <= 0 || t - last_sample < 2 * nudge) continue;
            last_sample = t;
            const float h = terrain::smooth_surface(grid_, ray.x0 + t * ray.ux, ray.y0 + t * ray.uy).z;
            if (std::isnan(h)) continue;
            const double tangent = (double(h) - ray.z0 - ray.curv * t * t) / t;
            if (tangent > ray.kz) {
                ray.kz = tangent;
                if (tangent >= ceiling_tan) return true;
            }
        }
        return false;
    });
    return ray.kz;
}

double SurfaceMarch::sun_visible_fraction(double x, double y, const glm::dvec3& sun, double sun_radius_rad,
                                          double curv) const {
    const terrain::HeightGrid& g = grid_;
    const double elevation = std::asin(std::clamp(sun.z, -1.0, 1.0));
    if (elevation + sun_radius_rad <= 0) return 0.0;
    const double hl = std::hypot(sun.x, sun.y);
    if (hl < 1e-9) return 1.0;
    const float z = terrain::smooth_surface(g, x, y).z;
    if (std::isnan(z)) return 1.0;
    const int row = std::clamp(int(std::lround(y)), 0, g.height - 1);
    const double dx = g.dx_m[std::size_t(row)], dy = g.dy_m[std::size_t(row)];
    const SurfaceRay ray{x, y, sun.x / hl / dx, -sun.y / hl / dy, double(z), 0.0, curv};
    double s_end = std::numeric_limits<double>::infinity();
    if (ray.ux > 0) s_end = std::min(s_end, (g.width - 1 - ray.x0) / ray.ux);
    if (ray.ux < 0) s_end = std::min(s_end, -ray.x0 / ray.ux);
    if (ray.uy > 0) s_end = std::min(s_end, (g.height - 1 - ray.y0) / ray.uy);
    if (ray.uy < 0) s_end = std::min(s_end, -ray.y0 / ray.uy);
    // Only the disc's band of elevations matters: below it the horizon hides nothing, above
    // it everything.
    constexpr double kNearVertical = 1.5;
    const double floor_tan = std::tan(std::max(elevation - sun_radius_rad, -kNearVertical));
    const double ceiling_tan = elevation + sun_radius_rad < kNearVertical ? std::tan(elevation + sun_radius_rad)
                                                                          : std::numeric_limits<double>::infinity();
    // The first sample a twentieth of a texel out: the receiver's own surface.
    const double step = std::min(dx, dy);
    const double tangent = horizon_tangent(ray, 0.05 * step, s_end, floor_tan, ceiling_tan, 1e-4 * step);
    return visibility::sun_disc_visible_fraction(std::atan(tangent), elevation, sun_radius_rad);
}

}  // namespace ts::render
