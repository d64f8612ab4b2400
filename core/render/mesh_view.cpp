#include "core/render/mesh_view.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "core/visibility/earth_curvature.hpp"

namespace ts::render {

MeshView::MeshView(const terrain::HeightGrid& grid, const PerspectiveView& view,
                   std::span<const PlacedMesh* const> meshes, bool curvature)
    : view_(view) {
    const PerspectiveView::Frame& f = view.frame();
    const int W = view.width(), H = view.height();
    const int sw = W * kSamples, sh = H * kSamples;
    const double curv = visibility::curvature_factor(curvature);
    // Per sample: the nearest fragment so far (sparse: only pixels a triangle touches).
    std::unordered_map<std::uint32_t, Covered> touched;
    auto to_camera = [&](const glm::dvec2 anchor, const glm::dvec3& p) {
        const glm::dvec3 g = anchor_frame_to_grid(grid, anchor, p, curv);
        const double e = (g.x - f.position.x) * f.dx, n = (f.position.y - g.y) * f.dy;
        return glm::dvec3(e, n, g.z - curv * (e * e + n * n) - f.position.z);
    };
    for (std::size_t mi = 0; mi < meshes.size(); ++mi) {
        const PlacedMesh& m = *meshes[mi];
        corners_.push_back(std::uint32_t(m.corners()));
        for (std::size_t t = 0; 3 * t + 2 < m.corners(); ++t) {
            glm::dvec3 v[3];
            double sx[3], sy[3], w[3];
            bool ok = true;
            for (int i = 0; i < 3; ++i) {
                v[i] = to_camera(m.anchor, m.positions[3 * t + i]);
                const double zf = glm::dot(v[i], f.forward);
                if (!(zf > kNearPlaneM)) {
                    ok = false;
                    break;
                }
                w[i] = 1.0 / zf;
                // Image-plane coordinates in samples (a pixel centre of sample units at s + 0.5).
                sx[i] = (glm::dot(v[i], f.right) * w[i] / f.half_width + 1.0) * 0.5 * sw;
                sy[i] = (1.0 - glm::dot(v[i], f.up) * w[i] / f.half_height) * 0.5 * sh;
            }
            if (!ok) continue;
            const double area = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sx[2] - sx[0]) * (sy[1] - sy[0]);
            if (!(std::abs(area) > 1e-12)) continue;
            const glm::dvec3 centroid = (v[0] + v[1] + v[2]) / 3.0;
            const glm::dvec3 normal = glm::dvec3(m.normals[3 * t]) + glm::dvec3(m.normals[3 * t + 1]) +
                                      glm::dvec3(m.normals[3 * t + 2]);
            const bool back = glm::dot(normal, centroid) > 0;
            const int x0 = std::max(0, int(std::floor(std::min({sx[0], sx[1], sx[2]}) - 0.5)));
            const int x1 = std::min(sw - 1, int(std::ceil(std::max({sx[0], sx[1], sx[2]}) - 0.5)));
            const int y0 = std::max(0, int(std::floor(std::min({sy[0], sy[1], sy[2]}) - 0.5)));
            const int y1 = std::min(sh - 1, int(std::ceil(std::max({sy[0], sy[1], sy[2]}) - 0.5)));
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x) {
                    const double px = x + 0.5, py = y + 0.5;
                    // Screen-space barycentrics (edge functions over the signed area).
                    const double l0 = ((sx[1] - px) * (sy[2] - py) - (sx[2] - px) * (sy[1] - py)) / area;
                    const double l1 = ((sx[2] - px) * (sy[0] - py) - (sx[0] - px) * (sy[2] - py)) / area;
                    const double l2 = 1.0 - l0 - l1;
                    if (l0 < 0 || l1 < 0 || l2 < 0) continue;
                    const double inv_z = l0 * w[0] + l1 * w[1] + l2 * w[2];
                    const double zf = 1.0 / inv_z;
                    const double a = (2.0 * px / sw - 1.0) * f.half_width, b = (1.0 - 2.0 * py / sh) * f.half_height;
                    const double distance = zf * std::sqrt(1.0 + a * a + b * b);
                    const int pi = x / kSamples, pj = y / kSamples;
                    const std::uint32_t pixel = std::uint32_t(pj) * W + pi;
                    if (!(distance < view.terrain_distance(pixel))) {
                        ++hidden_;
                        continue;
                    }
                    auto [it, fresh] = touched.try_emplace(pixel);
                    if (fresh) it->second.pixel = pixel;
                    Sample& s = it->second.samples[(y % kSamples) * kSamples + x % kSamples];
                    if (s.hit && s.distance <= distance) continue;
                    s.hit = true;
                    s.mesh = std::uint32_t(mi), s.triangle = std::uint32_t(t);
                    s.b1 = float(l1 * w[1] * zf), s.b2 = float(l2 * w[2] * zf);
                    s.distance = float(distance);
                    s.back = back;
                }
        }
    }
    covered_.reserve(touched.size());
    for (auto& [pixel, c] : touched)
        if (std::any_of(std::begin(c.samples), std::end(c.samples), [](const Sample& s) { return s.hit; }))
            covered_.push_back(c);
    std::sort(covered_.begin(), covered_.end(), [](const Covered& a, const Covered& b) { return a.pixel < b.pixel; });
}

void MeshView::compose(std::span<const std::vector<glm::vec3>> radiance, const light::SkyTable& sky,
                       std::vector<glm::vec3>& image) const {
    constexpr int kCount = kSamples * kSamples;
    for (const Covered& c : covered_) {
        const glm::vec3 terrain = image[c.pixel];
        const glm::vec3 dir = view_.ray_direction(c.pixel);
        glm::vec3 sum(0.0f);
        for (const Sample& s : c.samples) {
            if (!s.hit || s.mesh >= radiance.size()) {
                sum += terrain;
                continue;
            }
            const std::vector<glm::vec3>& r = radiance[s.mesh];
            const std::size_t corners = corners_[s.mesh];
            const std::size_t base = 3 * std::size_t(s.triangle) + (s.back ? corners : 0);
            if (base + 2 >= r.size()) {
                sum += terrain;
                continue;
            }
            const glm::vec3 lit = r[base] * (1.0f - s.b1 - s.b2) + r[base + 1] * s.b1 + r[base + 2] * s.b2;
            sum += view_.haze(lit, dir, s.distance, sky);
        }
        image[c.pixel] = sum / float(kCount);
    }
}

}  // namespace ts::render
