#include "core/visibility/blocker_log_sh.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/blockers/receiver_blockers.hpp"
#include "core/blockers/sphere_log_sh_kernel.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/util/parallel_for.hpp"
#include "core/visibility/blocker_footprint.hpp"

namespace ts::visibility {
namespace {

TexelRect intersect(const TexelRect& a, const TexelRect& b) {
    return {std::max(a.col0, b.col0), std::max(a.row0, b.row0), std::min(a.col1, b.col1), std::min(a.row1, b.row1)};
}

TexelRect bounding(const TexelRect& a, const TexelRect& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return {std::min(a.col0, b.col0), std::min(a.row0, b.row0), std::max(a.col1, b.col1), std::max(a.row1, b.row1)};
}

// The normals of the texels of `rect`, as terrain_normals gives them on the whole grid: the
// rectangle is cut out with a one-texel margin (central differences read the neighbours).
struct RectNormals {
    TexelRect with_margin;
    render::NormalField field;
    glm::dvec3 at(int c, int r) const {
        const std::size_t k = std::size_t(r - with_margin.row0) * std::size_t(with_margin.col1 - with_margin.col0) +
                              std::size_t(c - with_margin.col0);
        return {field.x[k], field.y[k], field.z[k]};
    }
};

RectNormals normals_of(const terrain::HeightGrid& g, const TexelRect& rect, int threads) {
    RectNormals out;
    out.with_margin = {std::max(0, rect.col0 - 1), std::max(0, rect.row0 - 1), std::min(g.width, rect.col1 + 1),
                       std::min(g.height, rect.row1 + 1)};
    const TexelRect& m = out.with_margin;
    const int w = m.col1 - m.col0, h = m.row1 - m.row0;
    std::vector<float> z(std::size_t(w) * std::size_t(h));
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) z[std::size_t(r) * std::size_t(w) + std::size_t(c)] = g.at(m.col0 + c, m.row0 + r);
    terrain::HeightGrid crop;
    crop.width = w, crop.height = h, crop.z = z;
    crop.dx_m.assign(g.dx_m.begin() + m.row0, g.dx_m.begin() + m.row1);
    crop.dy_m.assign(g.dy_m.begin() + m.row0, g.dy_m.begin() + m.row1);
    out.field = render::terrain_normals(crop, threads);
    return out;
}

// Whether a mesh's bounding sphere subtends more than the threshold from receiver q (or holds it).
// Each mesh's sky footprint inside the window, and the rectangle bounding them all.
struct WindowFootprints {
    std::vector<TexelRect> rects;
    TexelRect all;
};
WindowFootprints window_footprints(const terrain::HeightGrid& grid, const ReceiverWindow& window,
                                   const blockers::SphereBlockers& blockers, double min_sine) {
    WindowFootprints fp;
    const TexelRect win{window.col0, window.row0, window.col0 + window.width, window.row0 + window.height};
    for (const blockers::PlacedSpheres& m : blockers.meshes) {
        fp.rects.push_back(intersect(sky_footprint(grid, m, min_sine), win));
        fp.all = bounding(fp.all, fp.rects.back());
    }
    return fp;
}

bool bounding_sphere_counts(const blockers::PlacedSpheres& m, const glm::dvec3& q, double min_sine) {
    if (m.hierarchy.nodes.empty()) return false;
    const blockers::Sphere& root = m.hierarchy.nodes[0].bound;
    const glm::dvec3 v = root.center - q;
    const double d2 = glm::dot(v, v);
    return d2 <= root.radius * root.radius || root.radius / std::sqrt(d2) > min_sine;
}

}  // namespace

BlockerStageStats add_blocker_log_sh(const terrain::HeightGrid& grid, const ReceiverWindow& window,
                                     const blockers::SphereBlockers& blockers, double curvature,
                                     int threads, float* log_sh) {
    BlockerStageStats stats;
    if (blockers.empty()) return stats;
    const blockers::SphereBlockerOptions& opt = blockers.options;
    const double min_sine = blockers::min_cap_sine(opt.min_solid_angle_sr);
    const WindowFootprints fp = window_footprints(grid, window, blockers, min_sine);
    const std::vector<TexelRect>& rects = fp.rects;
    const TexelRect& all = fp.all;
    if (all.empty()) return stats;
    const RectNormals normals = normals_of(grid, all, threads);
    // Without culling: each mesh's spheres as lanes in its anchor frame, where the receiver is
    // placed (one mesh, the usual case, is accumulated straight from them; several are taken
    // relative to the receiver into one set, so the ratio attenuation sees them together).
    const bool cull = opt.sky_culling == blockers::SphereBlockerOptions::SkyCulling::hierarchy;
    std::vector<blockers::SphereLanes> mesh_lanes;
    if (!cull)
        for (const blockers::PlacedSpheres& m : blockers.meshes) mesh_lanes.emplace_back(m.spheres);
    const std::size_t texels = std::size_t(window.width) * std::size_t(window.height);
    std::atomic<long long> visited{0}, changed{0}, pairs{0};
    const int rows = all.row1 - all.row0;
    parallel_rows(rows, threads, (long long)(all.col1 - all.col0) * 64 * 100, [&](int b, int e) {
        blockers::SphereLanes seen;
        long long v = 0, ch = 0, pr = 0;
        for (int r = all.row0 + b; r < all.row0 + e; ++r)
            for (int c = all.col0; c < all.col1; ++c) {
                if (grid.is_hole(c, r)) continue;
                const glm::dvec3 n = normals.at(c, r);
                seen.clear();
                bool inside_any = false;
                // Without culling: the first mesh that counts here (accumulated from its own
                // lanes when it is the only one), and how many count.
                const blockers::PlacedSpheres* first = nullptr;
                std::size_t first_k = 0;
                glm::dvec3 first_q(0.0);
                int counted = 0;
                auto push_relative = [&](const blockers::PlacedSpheres& m, const glm::dvec3& q) {
                    for (const blockers::Sphere& s : m.spheres) seen.push_back({s.center - q, s.radius});
                };
                for (std::size_t k = 0; k < rects.size(); ++k) {
                    if (!rects[k].contains(c, r)) continue;
                    inside_any = true;
                    const blockers::PlacedSpheres& m = blockers.meshes[k];
                    const glm::dvec3 q = receiver_in_anchor_frame(grid, c, r, m, curvature);
                    if (cull) {
                        blockers::collect_sky_blockers(m, q, n, min_sine, opt.attenuation, seen);
                        continue;
                    }
                    if (!bounding_sphere_counts(m, q, min_sine)) continue;
                    if (++counted == 1) {
                        first = &m, first_k = k, first_q = q;
                        continue;
                    }
                    if (counted == 2) push_relative(*first, first_q);
                    push_relative(m, q);
                }
                v += inside_any;
                if (seen.empty() && counted != 1) continue;
                float add[16] = {};
                if (counted == 1)  // the mesh's own lanes, the receiver in its frame
                    blockers::accumulate_sphere_lanes(mesh_lanes[first_k], glm::vec3(first_q), glm::vec3(n),
                                                      float(opt.log_eps), opt.attenuation, add);
                else  // spheres relative to the receiver: it is the origin
                    blockers::accumulate_sphere_lanes(seen, glm::vec3(0.0f), glm::vec3(n), float(opt.log_eps),
                                                      opt.attenuation, add);
                const std::size_t t = std::size_t(r - window.row0) * std::size_t(window.width) +
                                      std::size_t(c - window.col0);
                for (int i = 0; i < 16; ++i) log_sh[std::size_t(i) * texels + t] += add[i];
                ++ch;
                pr += (long long)(counted == 1 ? mesh_lanes[first_k].size() : seen.size());
            }
        visited += v, changed += ch, pairs += pr;
    });
    stats.texels_visited = visited, stats.texels_changed = changed, stats.sphere_texel_pairs = pairs;
    return stats;
}

bool device_can_add_blockers(const blockers::SphereBlockers& blockers) {
    return blockers.options.sky_culling == blockers::SphereBlockerOptions::SkyCulling::none;
}

FlatBlockerReceivers flat_blocker_receivers(const terrain::HeightGrid& grid, const ReceiverWindow& window,
                                            const blockers::SphereBlockers& blockers, double curvature, int threads) {
    FlatBlockerReceivers out;
    if (blockers.empty() || !device_can_add_blockers(blockers)) return out;
    const double min_sine = blockers::min_cap_sine(blockers.options.min_solid_angle_sr);
    const WindowFootprints fp = window_footprints(grid, window, blockers, min_sine);
    const std::vector<TexelRect>& rects = fp.rects;
    const TexelRect& all = fp.all;
    if (all.empty()) return out;
    const RectNormals normals = normals_of(grid, all, threads);
    for (int r = all.row0; r < all.row1; ++r)
        for (int c = all.col0; c < all.col1; ++c) {
            if (grid.is_hole(c, r)) continue;
            bool inside_any = false, counted = false;
            for (std::size_t k = 0; k < rects.size(); ++k) {
                if (!rects[k].contains(c, r)) continue;
                inside_any = true;
                const blockers::PlacedSpheres& m = blockers.meshes[k];
                const glm::dvec3 q = receiver_in_anchor_frame(grid, c, r, m, curvature);
                if (!bounding_sphere_counts(m, q, min_sine)) continue;
                if (!counted)
                    out.texels.push_back(std::size_t(r - window.row0) * std::size_t(window.width) +
                                         std::size_t(c - window.col0));
                counted = true;
                out.receiver.push_back(std::uint32_t(out.texels.size() - 1));
                out.mesh.push_back(std::uint32_t(k));
                out.positions.emplace_back(q);
                out.normals.emplace_back(normals.at(c, r));
            }
            out.texels_visited += inside_any;
        }
    return out;
}

}  // namespace ts::visibility
