// `terrashade bench blockers`, the mesh itself: its self-shadow from its own bounding spheres
// (core/blockers/self_shadow.hpp, what the drawn mesh is lit with) against its triangles
// ray-traced (core/visibility/blocker_reference.hpp), at each sphere count of the bench: the
// cosine-weighted sky visibility about each surface point's normal, and the share of the sun's
// disc for six suns. Receivers are the triangles' centroids, each side of each face, those seen
// from outside.
#include "app/bench/bench_blockers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "core/blockers/placed_spheres.hpp"
#include "core/blockers/receiver_blockers.hpp"
#include "core/blockers/self_shadow.hpp"
#include "core/blockers/sun_disc_samples.hpp"
#include "core/blockers/triangle_bvh.hpp"
#include "core/sh/sh_exp.hpp"
#include "core/util/angles.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/stopwatch.hpp"
#include "core/visibility/blocker_reference.hpp"

namespace ts::app {
namespace {

struct Receiver {
    glm::dvec3 point, normal;
};

std::vector<Receiver> surface_receivers(const mesh::TriangleMesh& mesh) {
    std::vector<Receiver> out;
    for (std::size_t t = 0; t + 2 < mesh.positions.size(); t += 3) {
        const glm::dvec3 a(mesh.positions[t]), b(mesh.positions[t + 1]), c(mesh.positions[t + 2]);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        const double len = glm::length(n);
        if (!(len > 0)) continue;  // degenerate
        const glm::dvec3 centre = (a + b + c) / 3.0;
        out.push_back({centre, n / len});
        out.push_back({centre, -n / len});  // polygon soups: both sides, as the drawn mesh does
    }
    return out;
}

}  // namespace

void run_blocker_self_bench(const mesh::TriangleMesh& mesh, std::span<const blockers::SphereDecomposition> sets,
                            int threads) {
    const std::vector<Receiver> rec = surface_receivers(mesh);
    if (rec.empty() || sets.empty()) return;
    std::vector<glm::dvec3> p(mesh.positions.begin(), mesh.positions.end());
    const blockers::TriangleBvh bvh(p);
    const double offset = 1e-5 * glm::length(bvh.hi() - bvh.lo());
    const blockers::SphereBlockerOptions defaults;
    // Six suns in the model frame (z up): two azimuths, three elevations.
    std::vector<glm::dvec3> suns;
    for (double el : {10.0, 30.0, 60.0})
        for (double az : {45.0, 225.0})
            suns.push_back({std::cos(radians(el)) * std::cos(radians(az)), std::cos(radians(el)) * std::sin(radians(az)),
                            std::sin(radians(el))});
    const int strata = 16, sun_samples = 64;
    const sh::ShVec zenith = visibility::zenith_cosine_lobe();
    const Stopwatch tr;
    std::vector<double> ref_sky(rec.size());
    std::vector<double> ref_sun(rec.size() * suns.size());
    parallel_rows(int(rec.size()), threads, 256 + 64 * 6, [&](int b, int e) {
        for (int k = b; k < e; ++k) {
            const Receiver& r = rec[std::size_t(k)];
            ref_sky[std::size_t(k)] = visibility::reference_self_sky(bvh, r.point, r.normal, strata, offset);
            for (std::size_t s = 0; s < suns.size(); ++s)
                ref_sun[std::size_t(k) * suns.size() + s] = visibility::reference_self_sun(
                    bvh, r.point, r.normal, suns[s], defaults.sun_radius_rad, sun_samples, offset);
        }
    });
    // A side no ray leaves (inside a closed shell: the cabin, the far side of the skin) cannot be
    // seen from outside either; only the sides some ray leaves are compared.
    std::vector<std::size_t> seen;
    double mean_ref = 0;
    for (std::size_t k = 0; k < rec.size(); ++k)
        if (ref_sky[k] > 0.0) seen.push_back(k), mean_ref += ref_sky[k];
    if (seen.empty()) return;
    mean_ref /= double(seen.size());
    std::printf("\non the mesh itself: %zu of %zu receivers (each side of each triangle's centroid) seen from outside "
                "(some ray leaves them), its triangles ray-traced (%d sky rays, %d over the sun's disc, 6 suns) in %.2f "
                "s; their mean sky visibility %.3f\n",
                seen.size(), rec.size(), strata * strata, sun_samples, tr.seconds(), mean_ref);
    std::printf("%7s %9s %9s %9s %9s %9s %9s %9s\n", "spheres", "sky_rmse", "sky_bias", "sky_max", "sun_rmse",
                "sun_iou", "sky_ms", "sun_ms");
    for (const blockers::SphereDecomposition& d : sets) {
        std::vector<double> sky(rec.size()), sun(rec.size() * suns.size());
        const Stopwatch ts;
        parallel_rows(int(rec.size()), threads, 64 * int(d.spheres.size()), [&](int b, int e) {
            for (int k = b; k < e; ++k) {
                const Receiver& r = rec[std::size_t(k)];
                const sh::ShVec f =
                    blockers::self_shadow_log_sh(d.spheres, r.point, r.normal, defaults.log_eps, defaults.attenuation);
                float ff[16];
                for (int i = 0; i < 16; ++i) ff[i] = float(f[std::size_t(i)]);
                sky[std::size_t(k)] = visibility::sky_visibility_of_log_sh(ff, 1, sh::ExpMethod::scaling_squaring,
                                                                           visibility::cosine_lobe_about(zenith, r.normal));
            }
        });
        const double sky_s = ts.seconds();
        const Stopwatch tu;
        parallel_rows(int(rec.size()), threads, 6 * int(d.spheres.size()), [&](int b, int e) {
            for (int k = b; k < e; ++k)
                for (std::size_t s = 0; s < suns.size(); ++s)
                    sun[std::size_t(k) * suns.size() + s] =
                        blockers::self_shadow_sun(d.spheres, rec[std::size_t(k)].point, suns[s], defaults.sun_radius_rad);
        });
        const double sun_s = tu.seconds();
        double se = 0, bias = 0, worst = 0, sun_se = 0;
        long long both = 0, either = 0, lit = 0;
        for (std::size_t k : seen) {
            const double e = sky[k] - ref_sky[k];
            se += e * e, bias += e, worst = std::max(worst, std::abs(e));
            for (std::size_t s = 0; s < suns.size(); ++s) {
                if (glm::dot(rec[k].normal, suns[s]) <= 0.05) continue;  // faces away: dark on both sides
                const double a = sun[k * suns.size() + s], r = ref_sun[k * suns.size() + s];
                sun_se += (a - r) * (a - r), ++lit;
                both += a < 0.5 && r < 0.5, either += a < 0.5 || r < 0.5;
            }
        }
        const double n = double(seen.size());
        std::printf("%7zu %9.4f %+9.4f %9.4f %9.4f %9.3f %9.1f %9.1f\n", d.spheres.size(), std::sqrt(se / n), bias / n,
                    worst, lit ? std::sqrt(sun_se / double(lit)) : 0.0, either ? double(both) / double(either) : 1.0,
                    1e3 * sky_s, 1e3 * sun_s);
        std::fflush(stdout);
    }
    // The sun cast by the triangles, as the drawn mesh takes it by default (--mesh-sun-shadow
    // triangles): 16 rays over the disc from a hair off the surface (the renderer's offset,
    // 1e-4 of the mesh's radius), whatever the count.
    blockers::PlacedSpheres own;
    own.model_triangles = blockers::model_triangle_bvh(mesh);
    double tri_se = 0;
    long long tri_both = 0, tri_either = 0, tri_lit = 0;
    const Stopwatch tt;
    const double side_offset = 0.5e-4 * glm::length(bvh.hi() - bvh.lo());
    for (std::size_t s = 0; s < suns.size(); ++s) {
        const std::vector<glm::dvec3> disc = blockers::sun_disc_directions(suns[s], defaults.sun_radius_rad, defaults.sun_rays);
        for (std::size_t k : seen) {
            if (glm::dot(rec[k].normal, suns[s]) <= 0.05) continue;
            const double a = blockers::sun_visible_past_triangles(own, rec[k].point + side_offset * rec[k].normal, disc);
            const double r = ref_sun[k * suns.size() + s];
            tri_se += (a - r) * (a - r), ++tri_lit;
            tri_both += a < 0.5 && r < 0.5, tri_either += a < 0.5 || r < 0.5;
        }
    }
    std::printf("sun cast by the triangles (--mesh-sun-shadow triangles, the default, %d rays): RMSE %.4f, IoU %.3f, "
                "%.1f ms for the 6 suns\n",
                defaults.sun_rays, tri_lit ? std::sqrt(tri_se / double(tri_lit)) : 0.0,
                tri_either ? double(tri_both) / double(tri_either) : 1.0, 1e3 * tt.seconds());
    std::printf("sky: the cosine-weighted sky visibility about each receiver's normal, ours (its spheres' log-SH, the "
                "ones holding it ignored, exponentiated) - the triangles'; sun: over receivers facing each sun, the "
                "visible share of the disc, shadow = less than half (IoU)\n");
}

}  // namespace ts::app
