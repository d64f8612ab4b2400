#include "app/sphere_preview.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/raster/png_writer.hpp"
#include "core/util/atomic_file.hpp"

namespace ts::app {
namespace {

// One orthographic view: which model axes go right, up and towards the viewer.
struct View {
    int right, up, toward;
    double toward_sign;  // +1: the viewer looks down -toward
};
constexpr std::array<View, 3> kViews = {{{0, 1, 2, 1.0}, {0, 2, 1, -1.0}, {1, 2, 0, 1.0}}};

struct Canvas {
    int width, height;
    std::vector<std::uint8_t> rgb;
    void blend(int x, int y, const glm::dvec3& c, double alpha) {
        if (x < 0 || y < 0 || x >= width || y >= height) return;
        std::uint8_t* p = &rgb[std::size_t(3 * (y * width + x))];
        for (int k = 0; k < 3; ++k) p[k] = std::uint8_t(std::lround((1.0 - alpha) * p[k] + alpha * 255.0 * c[k]));
    }
};

glm::dvec3 hue(int i) {
    // Golden-angle hues, fully saturated, so neighbours differ.
    const double h = std::fmod(i * 0.618033988749895, 1.0) * 6.0;
    const double x = 1.0 - std::abs(std::fmod(h, 2.0) - 1.0);
    const int s = int(h);
    const glm::dvec3 c = s == 0 ? glm::dvec3(1, x, 0) : s == 1 ? glm::dvec3(x, 1, 0) : s == 2 ? glm::dvec3(0, 1, x)
                         : s == 3 ? glm::dvec3(0, x, 1) : s == 4 ? glm::dvec3(x, 0, 1) : glm::dvec3(1, 0, x);
    return 0.15 + 0.75 * c;
}

}  // namespace

void write_sphere_preview(const std::filesystem::path& png, const mesh::TriangleMesh& mesh,
                          std::span<const blockers::Sphere> spheres, int panel) {
    // One scale for all views: the box of mesh and spheres, with a margin.
    mesh::Bounds b = mesh::mesh_bounds(mesh);
    for (const blockers::Sphere& s : spheres) {
        b.lo = glm::min(b.lo, s.center - s.radius);
        b.hi = glm::max(b.hi, s.center + s.radius);
    }
    const glm::dvec3 mid = 0.5 * (b.lo + b.hi);
    const double extent = std::max({b.size().x, b.size().y, b.size().z, 1e-9});
    const double scale = 0.92 * panel / extent;  // pixels per metre

    const int gap = 4;
    Canvas canvas{3 * panel + 2 * gap, panel, {}};
    canvas.rgb.assign(std::size_t(canvas.width * canvas.height * 3), 255);
    for (int v = 0; v < 3; ++v) {
        const View& view = kViews[std::size_t(v)];
        const int x0 = v * (panel + gap);
        auto project = [&](const glm::dvec3& p) {
            return glm::dvec3(x0 + 0.5 * panel + (p[view.right] - mid[view.right]) * scale,
                              0.5 * panel - (p[view.up] - mid[view.up]) * scale,
                              view.toward_sign * (p[view.toward] - mid[view.toward]));
        };
        // Panel background, then the mesh with a depth buffer (nearest = largest depth).
        for (int y = 0; y < panel; ++y)
            for (int x = 0; x < panel; ++x) canvas.blend(x0 + x, y, glm::dvec3(1.0, 1.0, 1.0), 1.0);
        // Sphere fills first, under the mesh; outlines last, over it: both stay readable.
        auto draw_spheres = [&](bool outline) {
            for (int s = 0; s < int(spheres.size()); ++s) {
                const glm::dvec3 c = project(spheres[std::size_t(s)].center);
                const double r = spheres[std::size_t(s)].radius * scale;
                const glm::dvec3 colour = hue(s);
                for (int y = std::max(0, int(c.y - r - 1)); y <= std::min(panel - 1, int(c.y + r + 1)); ++y)
                    for (int x = std::max(x0, int(c.x - r - 1)); x <= std::min(x0 + panel - 1, int(c.x + r + 1)); ++x) {
                        const double d = std::hypot(x + 0.5 - c.x, y + 0.5 - c.y);
                        if (!outline && d <= r) canvas.blend(x, y, colour, 0.10);
                        if (outline && std::abs(d - r) < 0.5) canvas.blend(x, y, 0.6 * colour, 0.75);
                    }
            }
        };
        draw_spheres(false);
        std::vector<double> depth(std::size_t(panel * panel), std::numeric_limits<double>::lowest());
        glm::dvec3 toward(0.0);
        toward[view.toward] = view.toward_sign;
        const glm::dvec3 light = glm::normalize(toward + 0.5 * glm::dvec3(0.3, 0.2, 0.6));
        for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
            const glm::dvec3 a(mesh.positions[3 * t]), bb(mesh.positions[3 * t + 1]), c(mesh.positions[3 * t + 2]);
            glm::dvec3 n = glm::cross(bb - a, c - a);
            const double len = glm::length(n);
            if (!(len > 0)) continue;
            n /= len;
            const double shade = 0.12 + 0.5 * std::abs(glm::dot(n, light));  // two-sided: soups have no inside
            const glm::dvec3 p0 = project(a), p1 = project(bb), p2 = project(c);
            const double area = (p1.x - p0.x) * (p2.y - p0.y) - (p2.x - p0.x) * (p1.y - p0.y);
            if (std::abs(area) < 1e-12) continue;
            const int xa = std::max(x0, int(std::floor(std::min({p0.x, p1.x, p2.x}))));
            const int xb = std::min(x0 + panel - 1, int(std::ceil(std::max({p0.x, p1.x, p2.x}))));
            const int ya = std::max(0, int(std::floor(std::min({p0.y, p1.y, p2.y}))));
            const int yb = std::min(panel - 1, int(std::ceil(std::max({p0.y, p1.y, p2.y}))));
            for (int y = ya; y <= yb; ++y)
                for (int x = xa; x <= xb; ++x) {
                    const double px = x + 0.5, py = y + 0.5;
                    const double w0 = ((p1.x - px) * (p2.y - py) - (p2.x - px) * (p1.y - py)) / area;
                    const double w1 = ((p2.x - px) * (p0.y - py) - (p0.x - px) * (p2.y - py)) / area;
                    const double w2 = 1.0 - w0 - w1;
                    if (w0 < 0 || w1 < 0 || w2 < 0) continue;
                    const double z = w0 * p0.z + w1 * p1.z + w2 * p2.z;
                    double& d = depth[std::size_t(y * panel + (x - x0))];
                    if (z <= d) continue;
                    d = z;
                    canvas.blend(x, y, glm::dvec3(shade), 1.0);
                }
        }
        draw_spheres(true);
    }
    write_atomically(png, [&](const std::filesystem::path& tmp) {
        raster::write_png(tmp, png, canvas.width, canvas.height, 3, canvas.rgb.data());
    });
}

}  // namespace ts::app
