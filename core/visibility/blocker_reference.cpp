#include "core/visibility/blocker_reference.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/blockers/sun_disc_samples.hpp"
#include "core/sh/sh_basis.hpp"
#include "core/sh/sh_exp.hpp"
#include "core/util/angles.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/unit_frame.hpp"

namespace ts::visibility {
namespace {

std::vector<glm::dvec3> placed_positions(const mesh::TriangleMesh& m, const mesh::Placement& p, double ground) {
    mesh::validate(p);
    const glm::dmat3 rotation = mesh::placement_rotation(p);
    const double lift = p.height_m + (p.above_ground ? ground : 0.0);
    std::vector<glm::dvec3> out;
    out.reserve(m.positions.size());
    for (const glm::vec3& q : m.positions) {
        glm::dvec3 c = rotation * (glm::dvec3(q) * p.scale);
        c.z += lift;
        out.push_back(c);
    }
    return out;
}

glm::dvec3 receiver_at(const terrain::HeightGrid& g, int c, int r, glm::dvec2 anchor, double curvature) {
    const double e = (c - anchor.x) * g.dx_m[std::size_t(r)];
    const double n = (anchor.y - r) * g.dy_m[std::size_t(r)];
    return {e, n, double(g.at(c, r)) - (e * e + n * n) * curvature};
}

// Horizon elevation at internal azimuth phi (counter-clockwise from east), linear between the
// D directions.
double horizon_at(const HorizonSet& h, int c, int r, double phi) {
    const int D = h.directions;
    double x = phi / (2.0 * kPi) * D;
    x -= std::floor(x / D) * D;
    const int d0 = int(x) % D, d1 = (d0 + 1) % D;
    const double f = x - std::floor(x);
    return (1.0 - f) * h.at(d0, c, r) + f * h.at(d1, c, r);
}

}  // namespace

sh::ShVec zenith_cosine_lobe() {
    sh::ShVec lobe{};
    const int n = 400;
    for (int i = 0; i < n; ++i) {
        const double ct = (i + 0.5) / n;  // cos(theta) uniform in (0, 1): d omega = d(cos) d phi
        const double st = std::sqrt(1.0 - ct * ct);
        for (int j = 0; j < 2 * n; ++j) {
            const double phi = 2.0 * kPi * (j + 0.5) / (2 * n);
            const sh::ShVec y = sh::eval(glm::dvec3(st * std::cos(phi), st * std::sin(phi), ct));
            const double w = ct * (1.0 / n) * (2.0 * kPi / (2 * n));
            for (int k = 0; k < sh::kCount; ++k) lobe[std::size_t(k)] += w * y[std::size_t(k)];
        }
    }
    return lobe;
}

sh::ShVec cosine_lobe_about(const sh::ShVec& z, const glm::dvec3& n) {
    static_assert(sh::kBands == 4);
    // About +z the lobe is zonal: its m = 0 coefficients are the ZH coefficients zh_l.
    return sh::zh_rotate({z[0], z[2], z[6], z[12]}, n);
}

double reference_self_sky(const blockers::TriangleBvh& bvh, const glm::dvec3& point, const glm::dvec3& normal,
                          int strata, double offset) {
    glm::dvec3 t, b;
    unit_frame(normal, t, b);
    const glm::dvec3 o = point + offset * normal;
    const int s = std::max(1, strata);
    int seen = 0;
    for (int i = 0; i < s; ++i)
        for (int j = 0; j < s; ++j) {
            const double u = (i + 0.5) / s, phi = 2.0 * kPi * (j + 0.5) / s;
            const double rho = std::sqrt(u), z = std::sqrt(1.0 - u);
            seen += !bvh.occluded(o, rho * std::cos(phi) * t + rho * std::sin(phi) * b + z * normal);
        }
    return double(seen) / double(s * s);
}

double reference_self_sun(const blockers::TriangleBvh& bvh, const glm::dvec3& point, const glm::dvec3& normal,
                          const glm::dvec3& sun, double sun_radius, int sun_samples, double offset) {
    const glm::dvec3 o = point + offset * normal;
    const std::vector<glm::dvec3> dirs = blockers::sun_disc_directions(sun, sun_radius, sun_samples);
    int seen = 0;
    for (const glm::dvec3& d : dirs) seen += !bvh.occluded(o, d);
    return double(seen) / double(dirs.size());
}

PlacedTriangles place_triangles(const mesh::TriangleMesh& mesh, const mesh::Placement& placement, glm::dvec2 anchor,
                                double ground_height_m) {
    const std::vector<glm::dvec3> p = placed_positions(mesh, placement, ground_height_m);
    return {anchor, blockers::TriangleBvh(p)};
}

SkyReference reference_sky(const terrain::HeightGrid& grid, const HorizonSet& horizons, const PlacedTriangles& mesh,
                           const TexelRect& rect, double curvature, const ReferenceOptions& o) {
    SkyReference out;
    const std::size_t w = std::size_t(std::max(0, rect.col1 - rect.col0));
    const std::size_t n = rect.empty() ? 0 : w * std::size_t(rect.row1 - rect.row0);
    out.terrain.assign(n, 0.0f), out.with_mesh.assign(n, 0.0f);
    if (n == 0) return out;
    // Stratified cosine-weighted directions about the zenith: equal weights.
    struct Dir {
        glm::dvec3 d;
        double phi, elevation;
    };
    std::vector<Dir> dirs;
    const int s = std::max(1, o.sky_strata);
    for (int i = 0; i < s; ++i)
        for (int j = 0; j < s; ++j) {
            const double u = (i + 0.5) / s, phi = 2.0 * kPi * (j + 0.5) / s;
            const double rho = std::sqrt(u), z = std::sqrt(1.0 - u);
            dirs.push_back({{rho * std::cos(phi), rho * std::sin(phi), z}, phi, std::asin(z)});
        }
    const double weight = 1.0 / double(dirs.size());
    parallel_rows(rect.row1 - rect.row0, o.threads, (long long)w * (long long)dirs.size(), [&](int b, int e) {
        for (int r = rect.row0 + b; r < rect.row0 + e; ++r)
            for (int c = rect.col0; c < rect.col1; ++c) {
                const std::size_t k = std::size_t(r - rect.row0) * w + std::size_t(c - rect.col0);
                if (grid.is_hole(c, r)) {
                    out.terrain[k] = out.with_mesh[k] = NAN;
                    continue;
                }
                const glm::dvec3 p = receiver_at(grid, c, r, mesh.anchor, curvature);
                double t = 0.0, m = 0.0;
                for (const Dir& d : dirs) {
                    if (d.elevation <= horizon_at(horizons, c, r, d.phi)) continue;
                    t += weight;
                    if (!mesh.bvh.occluded(p, d.d)) m += weight;
                }
                out.terrain[k] = float(t), out.with_mesh[k] = float(m);
            }
    });
    return out;
}

std::vector<float> reference_sun(const terrain::HeightGrid& grid, const PlacedTriangles& mesh, const TexelRect& rect,
                                 const glm::dvec3& sun, double sun_radius, double curvature,
                                 const ReferenceOptions& o) {
    const std::size_t w = std::size_t(std::max(0, rect.col1 - rect.col0));
    const std::size_t n = rect.empty() ? 0 : w * std::size_t(rect.row1 - rect.row0);
    std::vector<float> out(n, 1.0f);
    if (n == 0) return out;
    const std::vector<glm::dvec3> dirs = blockers::sun_disc_directions(sun, sun_radius, o.sun_samples);
    const int m = int(dirs.size());
    parallel_rows(rect.row1 - rect.row0, o.threads, (long long)w * m, [&](int b, int e) {
        for (int r = rect.row0 + b; r < rect.row0 + e; ++r)
            for (int c = rect.col0; c < rect.col1; ++c) {
                const std::size_t k = std::size_t(r - rect.row0) * w + std::size_t(c - rect.col0);
                if (grid.is_hole(c, r)) {
                    out[k] = NAN;
                    continue;
                }
                const glm::dvec3 p = receiver_at(grid, c, r, mesh.anchor, curvature);
                int seen = 0;
                for (const glm::dvec3& d : dirs) seen += !mesh.bvh.occluded(p, d);
                out[k] = float(double(seen) / m);
            }
    });
    return out;
}

double sky_visibility_of_log_sh(const float* f, std::size_t stride, sh::ExpMethod method, const sh::ShVec& lobe) {
    float in[16], v[16];
    for (int i = 0; i < 16; ++i) in[i] = f[std::size_t(i) * stride];
    sh::sh_exp(method, in, v);
    double s = 0.0;
    for (int i = 0; i < 16; ++i) s += double(v[i]) * lobe[std::size_t(i)];
    return s / kPi;
}

}  // namespace ts::visibility
