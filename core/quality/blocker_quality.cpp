#include "core/quality/blocker_quality.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>

namespace ts::quality {
namespace {

// A raster over the plane perpendicular to the sun, cells of side h from `lo`.
struct Silhouette {
    glm::dvec2 lo{0.0};
    double h = 1;
    int nx = 0, ny = 0;
    std::vector<std::uint8_t> triangles, spheres;

    glm::dvec2 centre(int i, int j) const { return lo + glm::dvec2((i + 0.5) * h, (j + 0.5) * h); }
    // Cell index range [i0, i1) covering [a, b] on an axis of n cells from origin o.
    void range(double a, double b, double o, int n, int& i0, int& i1) const {
        i0 = std::clamp(int(std::floor((a - o) / h - 0.5)), 0, n);
        i1 = std::clamp(int(std::ceil((b - o) / h + 0.5)), 0, n);
    }
};

double edge(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

void fill_triangle(Silhouette& s, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    double area = edge(a, b, c);
    if (area == 0) return;  // edge-on: no area to shade
    if (area < 0) std::swap(b, c);
    int i0, i1, j0, j1;
    s.range(std::min({a.x, b.x, c.x}), std::max({a.x, b.x, c.x}), s.lo.x, s.nx, i0, i1);
    s.range(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}), s.lo.y, s.ny, j0, j1);
    for (int j = j0; j < j1; ++j)
        for (int i = i0; i < i1; ++i) {
            const glm::dvec2 p = s.centre(i, j);
            if (edge(a, b, p) >= 0 && edge(b, c, p) >= 0 && edge(c, a, p) >= 0)
                s.triangles[std::size_t(j) * std::size_t(s.nx) + std::size_t(i)] = 1;
        }
}

void fill_disc(Silhouette& s, glm::dvec2 c, double r) {
    int i0, i1, j0, j1;
    s.range(c.x - r, c.x + r, s.lo.x, s.nx, i0, i1);
    s.range(c.y - r, c.y + r, s.lo.y, s.ny, j0, j1);
    for (int j = j0; j < j1; ++j)
        for (int i = i0; i < i1; ++i) {
            const glm::dvec2 d = s.centre(i, j) - c;
            if (glm::dot(d, d) <= r * r) s.spheres[std::size_t(j) * std::size_t(s.nx) + std::size_t(i)] = 1;
        }
}

}  // namespace

const std::vector<int>& candidate_sphere_counts() {
    static const std::vector<int> counts = {8, 16, 32, 64, 128, 256, 512};
    return counts;
}

ShadowOutline flat_shadow_outline(const mesh::TriangleMesh& mesh, std::span<const blockers::Sphere> model_spheres,
                                  const mesh::Placement& placement, const glm::dvec3& sun, int cells) {
    ShadowOutline out;
    if (!(sun.z > 0) || model_spheres.empty() || mesh.positions.empty()) return out;
    const glm::dvec3 s = glm::normalize(sun);
    // Orthonormal axes of the plane perpendicular to the sun.
    const glm::dvec3 e1 = std::abs(s.z) > 0.999999 ? glm::dvec3(1, 0, 0)
                                                   : glm::normalize(glm::cross(glm::dvec3(0, 0, 1), s));
    const glm::dvec3 e2 = glm::cross(s, e1);
    const glm::dmat3 to_enu = mesh::placement_rotation(placement) * placement.scale;
    const auto project = [&](const glm::dvec3& model) {
        const glm::dvec3 p = to_enu * model;
        return glm::dvec2(glm::dot(p, e1), glm::dot(p, e2));
    };
    std::vector<glm::dvec2> corners(mesh.positions.size());
    glm::dvec2 lo(INFINITY), hi(-INFINITY);
    for (std::size_t k = 0; k < corners.size(); ++k) {
        corners[k] = project(glm::dvec3(mesh.positions[k]));
        lo = glm::min(lo, corners[k]), hi = glm::max(hi, corners[k]);
    }
    std::vector<glm::dvec2> centres(model_spheres.size());
    std::vector<double> radii(model_spheres.size());
    for (std::size_t k = 0; k < centres.size(); ++k) {
        centres[k] = project(model_spheres[k].center);
        radii[k] = model_spheres[k].radius * placement.scale;
        lo = glm::min(lo, centres[k] - radii[k]), hi = glm::max(hi, centres[k] + radii[k]);
    }
    Silhouette sil;
    const double extent = std::max(hi.x - lo.x, hi.y - lo.y);
    if (!(extent > 0)) return out;
    sil.h = extent / std::max(8, cells);
    sil.lo = lo;
    sil.nx = std::max(1, int(std::ceil((hi.x - lo.x) / sil.h)));
    sil.ny = std::max(1, int(std::ceil((hi.y - lo.y) / sil.h)));
    const std::size_t n = std::size_t(sil.nx) * std::size_t(sil.ny);
    sil.triangles.assign(n, 0), sil.spheres.assign(n, 0);
    for (std::size_t k = 0; k + 2 < corners.size(); k += 3) fill_triangle(sil, corners[k], corners[k + 1], corners[k + 2]);
    for (std::size_t k = 0; k < centres.size(); ++k) fill_disc(sil, centres[k], radii[k]);
    std::size_t tri = 0, sph = 0, differ = 0;
    for (std::size_t k = 0; k < n; ++k) tri += sil.triangles[k], sph += sil.spheres[k], differ += sil.triangles[k] != sil.spheres[k];
    // A silhouette area a falls on flat ground as a / sin(elevation).
    const double cell_on_ground = sil.h * sil.h / s.z;
    out.triangle_area_m2 = double(tri) * cell_on_ground;
    out.sphere_area_m2 = double(sph) * cell_on_ground;
    out.mismatch_area_m2 = double(differ) * cell_on_ground;
    return out;
}

MeshErrorTerms predicted_mesh_error(const mesh::TriangleMesh& mesh, std::span<const blockers::Sphere> model_spheres,
                                    const mesh::Placement& placement, std::span<const BlockerSun> suns,
                                    const PictureArea& picture, double sky_footprint_area_m2, bool sun_by_triangles) {
    MeshErrorTerms e;
    if (!(picture.area_m2 > 0)) return e;
    for (const BlockerSun& sun : suns) {
        if (!(sun.direction.z > 0)) continue;  // no sun light to shadow
        const ShadowOutline o =
            sun_by_triangles ? ShadowOutline{} : flat_shadow_outline(mesh, model_spheres, placement, sun.direction);
        // A lit texel's direct sun over the picture's mean: sin e / mean(max(0, n.s)); a picture
        // with hardly any lit ground is held at 1% of the sun's flat-ground light.
        const double share = sun.direction.z / std::max(sun.mean_lit_cosine, 0.01 * sun.direction.z);
        const double outline = std::sqrt(o.mismatch_area_m2) + std::sqrt(std::max(0.0, picture.texel_area_m2));
        e.sun = std::max(e.sun, kSunOutlineMargin * share * outline / std::sqrt(picture.area_m2));
    }
    e.sky = kSkyFootprintRmse * std::sqrt(std::max(0.0, sky_footprint_area_m2) / picture.area_m2);
    return e;
}

SphereCountChoice choose_sphere_count(double budget, const std::function<double(int)>& error_of) {
    SphereCountChoice best;
    best.met = false;
    bool first = true;
    for (int count : candidate_sphere_counts()) {
        const double e = error_of(count);
        if (e <= budget) return {count, e, true};
        if (first || e < best.predicted_error) best.spheres = count, best.predicted_error = e;
        first = false;
    }
    return best;
}

}  // namespace ts::quality
