#include "core/visibility/blocker_footprint.hpp"

#include <algorithm>
#include <cmath>

namespace ts::visibility {
namespace {

// The texels whose centres may lie in the box [e0, e1] x [n0, n1] (metres of the anchor frame).
// Metres become texels with the smallest spacing of any row, so the rectangle holds the box on
// every row of a geographic grid; one texel of slack on each side for rounding.
TexelRect box_to_texels(const terrain::HeightGrid& g, const glm::dvec2& anchor, double e0, double e1, double n0,
                        double n1) {
    if (g.width <= 0 || g.height <= 0 || !(e1 >= e0) || !(n1 >= n0)) return {};
    const double dx = *std::min_element(g.dx_m.begin(), g.dx_m.end());
    const double dy = *std::min_element(g.dy_m.begin(), g.dy_m.end());
    auto clamp_to = [](double v, int hi) { return int(std::clamp(v, 0.0, double(hi))); };
    TexelRect r;
    r.col0 = clamp_to(std::floor(anchor.x + e0 / dx) - 1.0, g.width);
    r.col1 = clamp_to(std::ceil(anchor.x + e1 / dx) + 2.0, g.width);
    r.row0 = clamp_to(std::floor(anchor.y - n1 / dy) - 1.0, g.height);
    r.row1 = clamp_to(std::ceil(anchor.y - n0 / dy) + 2.0, g.height);
    return r;
}

}  // namespace

TexelRect sky_footprint(const terrain::HeightGrid& g, const blockers::PlacedSpheres& mesh, double min_sine) {
    if (mesh.hierarchy.nodes.empty()) return {};
    const blockers::Sphere& root = mesh.hierarchy.nodes[0].bound;
    const double reach = root.radius / std::max(min_sine, 1e-6);
    return box_to_texels(g, mesh.anchor, root.center.x - reach, root.center.x + reach, root.center.y - reach,
                         root.center.y + reach);
}

TexelRect sun_footprint(const terrain::HeightGrid& g, const blockers::PlacedSpheres& mesh, const glm::dvec3& sun,
                        double sun_radius, double z_low, double z_high) {
    if (mesh.hierarchy.nodes.empty() || sun.z <= 0.0) return {};
    const blockers::Sphere& root = mesh.hierarchy.nodes[0].bound;
    // A receiver above the sphere's top sees all of it below the horizontal, the sun above.
    const double top = std::min(z_high, root.center.z + root.radius);
    if (top < z_low) return {};
    const double sin_e = sun.z;
    // Along the sun's ray from a receiver at height z to the sphere's centre height: the ray
    // length L = (c.z - z) / sin e; the penumbra cone adds L tan(alpha) to the radius. The
    // cylinder's cross-section with a horizontal plane is an ellipse of semi-axes R' and R' / sin e.
    const double far = std::max(0.0, root.center.z - z_low) / sin_e + root.radius;
    const double radius = (root.radius + far * std::tan(sun_radius) * 1.01) / sin_e + 1e-3;
    const glm::dvec2 back = -glm::dvec2(sun.x, sun.y) / sin_e;  // horizontal shift per metre of drop
    const glm::dvec2 c(root.center.x, root.center.y);
    const glm::dvec2 p0 = c + back * (root.center.z - top), p1 = c + back * (root.center.z - z_low);
    return box_to_texels(g, mesh.anchor, std::min(p0.x, p1.x) - radius, std::max(p0.x, p1.x) + radius,
                         std::min(p0.y, p1.y) - radius, std::max(p0.y, p1.y) + radius);
}

HeightRange height_range(const terrain::HeightGrid& g) {
    double lo = INFINITY, hi = -INFINITY;
    for (float z : g.z)
        if (!std::isnan(z)) lo = std::min(lo, double(z)), hi = std::max(hi, double(z));
    if (lo > hi) return {};
    return {lo, hi};
}

double largest_curvature_drop(const terrain::HeightGrid& g, const blockers::PlacedSpheres& mesh, double curvature) {
    const double dx = g.dx_m.empty() ? 0.0 : *std::max_element(g.dx_m.begin(), g.dx_m.end());
    const double dy = g.dy_m.empty() ? 0.0 : *std::max_element(g.dy_m.begin(), g.dy_m.end());
    const double e = std::max(std::abs(mesh.anchor.x), std::abs(g.width - 1 - mesh.anchor.x)) * dx;
    const double n = std::max(std::abs(mesh.anchor.y), std::abs(g.height - 1 - mesh.anchor.y)) * dy;
    return (e * e + n * n) * curvature;
}

}  // namespace ts::visibility
