#include "core/render/mesh_lighting.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include <glm/geometric.hpp>

#include "core/blockers/receiver_blockers.hpp"
#include "core/blockers/self_shadow.hpp"
#include "core/blockers/sun_disc_samples.hpp"
#include "core/render/diffuse_band_correction.hpp"
#include "core/render/transfer.hpp"
#include "core/sh/slice_projector.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/stopwatch.hpp"
#include "core/visibility/earth_curvature.hpp"

namespace ts::render {
namespace {

struct PointLess {
    bool operator()(const glm::dvec3& a, const glm::dvec3& b) const {
        if (a.x != b.x) return a.x < b.x;
        if (a.y != b.y) return a.y < b.y;
        return a.z < b.z;
    }
};

}  // namespace

PlacedMesh place_mesh(const mesh::TriangleMesh& m, const mesh::Placement& placement, glm::dvec2 anchor,
                      double ground_height_m, std::string name) {
    mesh::validate(placement);
    const glm::dmat3 rotation = mesh::placement_rotation(placement);
    const double lift = placement.height_m + (placement.above_ground ? ground_height_m : 0.0);
    PlacedMesh p;
    p.name = std::move(name);
    p.anchor = anchor;
    p.positions.reserve(m.positions.size());
    p.normals.reserve(m.positions.size());
    for (std::size_t k = 0; k < m.positions.size(); ++k) {
        glm::dvec3 c = rotation * (glm::dvec3(m.positions[k]) * placement.scale);
        c.z += lift;
        p.positions.push_back(c);
        glm::dvec3 n = rotation * glm::dvec3(k < m.normals.size() ? m.normals[k] : glm::vec3(0, 0, 1));
        const double len = glm::length(n);
        p.normals.push_back(len > 0 ? glm::vec3(n / len) : glm::vec3(0, 0, 1));
    }
    p.albedo.reserve(m.triangle_count());
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
        const std::uint32_t id = m.material[t];
        const glm::vec4 c = id < m.materials.size() ? m.materials[id].base_color : glm::vec4(0.8f);
        p.albedo.push_back(glm::clamp(glm::vec3(c), glm::vec3(0.0f), glm::vec3(1.0f)));
    }
    return p;
}

glm::dvec3 anchor_frame_to_grid(const terrain::HeightGrid& g, glm::dvec2 anchor, const glm::dvec3& p,
                                double curvature) {
    const int row = std::clamp(int(std::lround(anchor.y)), 0, g.height - 1);
    const double dx = g.dx_m[std::size_t(row)], dy = g.dy_m[std::size_t(row)];
    // The frame is tangent at the anchor: the datum falls away from it by the curvature drop.
    return {anchor.x + p.x / dx, anchor.y - p.y / dy, p.z + curvature * (p.x * p.x + p.y * p.y)};
}

MeshLighting::MeshLighting(const terrain::HeightGrid& grid, PlacedMesh mesh, const blockers::PlacedSpheres* spheres,
                           const blockers::SphereBlockerOptions& sphere_options, const MeshLightingOptions& options)
    : grid_(grid),
      mesh_(std::move(mesh)),
      spheres_(spheres),
      sphere_options_(sphere_options),
      options_(options),
      horizons_(grid, visibility::PointHorizonOptions{options.curvature}) {
    const Stopwatch clock;
    const std::size_t corners = mesh_.corners();
    const std::size_t n = 2 * corners;
    // Distinct positions: a soup repeats each vertex for every triangle around it.
    std::map<glm::dvec3, std::uint32_t, PointLess> index;
    point_of_.resize(corners);
    for (std::size_t k = 0; k < corners; ++k) {
        const auto [it, fresh] = index.emplace(mesh_.positions[k], std::uint32_t(points_.size()));
        if (fresh) points_.push_back(mesh_.positions[k]);
        point_of_[k] = it->second;
    }
    const double curvature = visibility::curvature_factor(options_.curvature);
    grid_points_.resize(points_.size());
    for (std::size_t i = 0; i < points_.size(); ++i)
        grid_points_[i] = anchor_frame_to_grid(grid_, mesh_.anchor, points_[i], curvature);

    // The terrain's log-SH per distinct point.
    const int dirs = std::max(4, options_.directions);
    std::vector<float> terrain_log(points_.size() * 16, 0.0f);
    if (options_.terrain_shadow) {
        const sh::SliceProjector projector(dirs);
        parallel_for(int(points_.size()), thread_count(options_.threads), [&](int i, int) {
            std::vector<float> sigma(static_cast<std::size_t>(dirs));
            const glm::dvec3& q = grid_points_[std::size_t(i)];
            horizons_.horizons({q.x, q.y}, q.z, dirs, sigma.data());
            projector.project_horizons(sigma.data(), options_.terrain_log_eps, &terrain_log[std::size_t(i) * 16]);
        });
    }
    // Plus the own spheres' per receiver (their culling and ratio depend on the normal).
    log_sh_.assign(16 * n, 0.0f);
    std::vector<float> axis(3 * n);
    parallel_for(int(n), thread_count(options_.threads), [&](int r, int) {
        const std::size_t k = std::size_t(r) % corners;
        const glm::vec3 normal = std::size_t(r) < corners ? mesh_.normals[k] : -mesh_.normals[k];
        axis[3 * std::size_t(r)] = normal.x, axis[3 * std::size_t(r) + 1] = normal.y, axis[3 * std::size_t(r) + 2] = normal.z;
        sh::ShVec self{};
        if (options_.self_shadow && spheres_)
            self = blockers::self_shadow_log_sh(spheres_->spheres, mesh_.positions[k], glm::dvec3(normal),
                                                sphere_options_.log_eps, sphere_options_.attenuation);
        const float* t = &terrain_log[std::size_t(point_of_[k]) * 16];
        for (int i = 0; i < 16; ++i) log_sh_[std::size_t(i) * n + std::size_t(r)] = t[i] + float(self[std::size_t(i)]);
    });

    const sh::LogBrdfTable table(options_.brdf_log_eps);
    const sh::ZhVec zh = table.diffuse();
    const std::array<float, 4> lobe = {float(zh[0]), float(zh[1]), float(zh[2]), float(zh[3])};
    TransferInputs in;
    in.texels = n;
    in.log_visibility = log_sh_.data();
    in.lobe_axis = axis.data();
    in.lobe_log_zh = lobe.data();
    in.uniform_lobe = true;
    in.method = options_.exp_method;
    in.threads = options_.threads;
    transfer_.resize(16 * n);
    if (n > 0) {
        transfer_vectors(in, transfer_.data());
        if (options_.band_correction) correct_diffuse_bands(lobe, in.method, transfer_.data(), n);
    }
    seconds_ = clock.seconds();
}

void MeshLighting::sun_visibility(const glm::dvec3& sun, std::vector<float>& out) const {
    const std::size_t corners = mesh_.corners();
    out.resize(2 * corners);
    std::vector<float> terrain(points_.size(), 1.0f);
    if (options_.terrain_shadow) {
        parallel_for(int(points_.size()), thread_count(options_.threads), [&](int i, int) {
            const glm::dvec3& q = grid_points_[std::size_t(i)];
            terrain[std::size_t(i)] = float(horizons_.sun_fraction({q.x, q.y}, q.z, sun, sphere_options_.sun_radius_rad));
        });
    }
    // The sun on the mesh from its own triangles (sun_caster = triangles, as on the terrain):
    // rays over the disc from each side of a corner, a hair off the surface along that side's
    // normal so the corner's own faces do not hide it; else from its spheres, analytically.
    const bool by_triangles = options_.self_shadow && spheres_ && spheres_->model_triangles &&
                              sphere_options_.sun_caster == blockers::SphereBlockerOptions::SunCaster::triangles;
    const std::vector<glm::dvec3> disc =
        by_triangles ? blockers::sun_disc_directions(sun, sphere_options_.sun_radius_rad, sphere_options_.sun_rays)
                     : std::vector<glm::dvec3>{};
    const double offset =
        by_triangles && !spheres_->hierarchy.nodes.empty() ? 1e-4 * spheres_->hierarchy.nodes[0].bound.radius : 0.0;
    parallel_for(int(corners), thread_count(options_.threads), [&](int k, int) {
        const double v = terrain[point_of_[std::size_t(k)]];
        const glm::dvec3& p = mesh_.positions[std::size_t(k)];
        if (by_triangles) {
            const glm::dvec3 n(mesh_.normals[std::size_t(k)]);
            const double front = v > 0 ? blockers::sun_visible_past_triangles(*spheres_, p + offset * n, disc) : 0.0;
            const double back = v > 0 ? blockers::sun_visible_past_triangles(*spheres_, p - offset * n, disc) : 0.0;
            out[std::size_t(k)] = float(std::clamp(v * front, 0.0, 1.0));
            out[corners + std::size_t(k)] = float(std::clamp(v * back, 0.0, 1.0));
            return;
        }
        double w = v;
        if (w > 0 && options_.self_shadow && spheres_)
            w *= blockers::self_shadow_sun(spheres_->spheres, p, sun, sphere_options_.sun_radius_rad);
        // Both sides of a corner stand at the same point: the spheres hide the sun from it or not alike.
        out[std::size_t(k)] = out[corners + std::size_t(k)] = float(std::clamp(w, 0.0, 1.0));
    });
}

void MeshLighting::radiance(const light::SkySh& sky_sh, const light::SunDisc& sun, bool sun_up,
                            std::vector<glm::vec3>& out) const {
    const std::size_t corners = mesh_.corners();
    const std::size_t n = 2 * corners;
    out.resize(n);
    std::vector<float> vis;
    if (sun_up) sun_visibility(sun.direction, vis);
    const glm::vec3 s = glm::vec3(sun.direction);
    const glm::vec3 e_diffuse = sun_up ? glm::vec3(sun.irradiance) * float(1.0 / std::numbers::pi) : glm::vec3(0.0f);
    for (std::size_t r = 0; r < n; ++r) {
        const std::size_t k = r % corners;
        glm::vec3 sky(0.0f);
        for (int i = 0; i < 16; ++i) sky += transfer_[std::size_t(i) * n + r] * glm::vec3(sky_sh[std::size_t(i)]);
        // SH ringing can dip a dark receiver's sky light below zero: no light is negative.
        sky = glm::max(sky, glm::vec3(0.0f));
        const glm::vec3 normal = r < corners ? mesh_.normals[k] : -mesh_.normals[k];
        const float cos_s = std::max(0.0f, glm::dot(normal, s));
        const glm::vec3 sun_term = sun_up ? vis[r] * cos_s * e_diffuse : glm::vec3(0.0f);
        out[r] = mesh_.albedo[k / 3] * (sky + sun_term);
    }
}

}  // namespace ts::render
