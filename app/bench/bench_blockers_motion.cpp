// `terrashade bench blockers`, second part: a 400-sphere aircraft flying over a 1000 x 1000 DEM.
// Per frame the sky log-SH of the texels in the old footprint is restored and the new
// footprint's recomputed, and the sun shadow applied: through the sphere hierarchy (threshold
// and tangent-plane culling of whole subtrees, blocker_log_sh.hpp), and as a flat loop that
// takes every sphere at every footprint texel where the mesh's bounding sphere passes the
// threshold (`--sphere-culling none`: no hierarchy, each sphere above the plane kept, what a
// brute-force kernel over texels x spheres does); the flat loop also on the Vulkan device.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <vector>

#include "app/bench/bench_blockers.hpp"
#include "core/blockers/sphere_decomposition.hpp"
#include "core/dem/read_dem.hpp"
#include "core/mesh/mesh_import.hpp"
#include "core/render/scene_blockers.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/util/stopwatch.hpp"
#include "core/visibility/blocker_footprint.hpp"
#include "core/visibility/blocker_log_sh.hpp"
#include "core/visibility/blocker_reference.hpp"
#include "core/visibility/blocker_sun_shadow.hpp"
#include "core/visibility/earth_curvature.hpp"
#ifdef TERRASHADE_HAS_GPU
#include "gpu/context.hpp"
#include "gpu/visibility/gpu_blocker_log_sh.hpp"
#endif

namespace ts::app {
namespace {

// Restores the base log-SH in `rect` (the footprint the mesh leaves).
void restore(const std::vector<float>& base, std::vector<float>& log_sh, const visibility::TexelRect& rect, int width,
             std::size_t texels) {
    if (rect.empty()) return;
    for (int i = 0; i < 16; ++i)
        for (int r = rect.row0; r < rect.row1; ++r) {
            const std::size_t a = std::size_t(i) * texels + std::size_t(r) * width + rect.col0;
            std::copy(base.begin() + std::ptrdiff_t(a), base.begin() + std::ptrdiff_t(a + (rect.col1 - rect.col0)),
                      log_sh.begin() + std::ptrdiff_t(a));
        }
}

#ifdef TERRASHADE_HAS_GPU
// The flat loop of one frame on the best Vulkan device (blocker_log_sh.comp: every sphere at
// every footprint texel where the mesh's bounding sphere passes the threshold, as the CPU's
// `none` culling selects them), timed from upload to download, and its sky visibility against
// the CPU's of the same frame. Prints why when there is no device.
void run_flat_on_vulkan(const terrain::HeightGrid& g, const blockers::SphereBlockers& b, double curvature,
                        int threads, const std::vector<float>& cpu_log_sh) {
    std::unique_ptr<gpu::Context> context;
    try {
        context = std::make_unique<gpu::Context>();
    } catch (const std::exception& e) {
        std::printf("%-26s not run: %s\n", "flat on Vulkan", e.what());
        return;
    }
    const blockers::PlacedSpheres& m = b.meshes[0];
    // The receivers the Vulkan visibility backend gathers (the whole grid is the window, so
    // their indices are grid texels).
    const visibility::FlatBlockerReceivers rec =
        visibility::flat_blocker_receivers(g, {0, 0, g.width, g.height}, b, curvature, threads);
    const std::size_t n = rec.texels.size();
    std::vector<float> log_sh(16 * n, 0.0f);
    const gpu::visibility::GpuBlockerLogSh kernel(*context);
    const double ms = kernel.add(rec.positions, rec.normals, m.spheres, float(b.options.log_eps), b.options.attenuation, log_sh);
    const double pairs = double(n) * double(m.spheres.size());
    const sh::ShVec lobe = visibility::zenith_cosine_lobe();
    const std::size_t texels = std::size_t(g.width) * g.height;
    double worst = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double a = visibility::sky_visibility_of_log_sh(log_sh.data() + k, n, sh::ExpMethod::scaling_squaring, lobe);
        const double want = visibility::sky_visibility_of_log_sh(cpu_log_sh.data() + rec.texels[k], texels,
                                                                 sh::ExpMethod::scaling_squaring, lobe);
        worst = std::max(worst, std::abs(a - want));
    }
    std::printf("%-26s %10.1f %10s %14.0f %14.3g   (%s, one frame; sky visibility max %.2g off the CPU's)\n",
                "flat on Vulkan", ms, "-", pairs, pairs / (1e-3 * ms), context->device_info().name.c_str(), worst);
}
#endif

}  // namespace

void run_blocker_motion_bench(const BenchBlockersOptions& o) {
    const dem::Dem dem = dem::read_dem(o.motion_dem);
    const terrain::HeightGrid grid = terrain::metric_view(dem);
    const mesh::TriangleMesh mesh = mesh::import_mesh(o.mesh);
    blockers::DecompositionOptions d;
    d.count = o.motion_spheres, d.threads = o.threads;
    const blockers::SphereDecomposition dec = blockers::decompose_into_spheres(mesh, d);
    const std::shared_ptr<const blockers::TriangleBvh> triangles = blockers::model_triangle_bvh(mesh);
    const double curvature = visibility::curvature_factor(true);
    const std::size_t texels = std::size_t(grid.width) * grid.height;
    // The terrain's log-SH stands in as zeros: the bench measures the blockers' share.
    const std::vector<float> base(16 * texels, 0.0f);
    std::printf("\nmoving aircraft: %s, %zu spheres, x%.0f, %.0f m agl over %s (%dx%d), %d frames, %d threads\n",
                o.mesh.c_str(), dec.spheres.size(), o.scale, o.at[2], o.motion_dem.c_str(), grid.width, grid.height,
                o.motion_frames, o.threads);
    // A straight path across the middle of the grid, west to east, ~1.5 texels a frame.
    const geo::Georef& gr = dem.georef;
    auto place_at = [&](int frame) {
        mesh::Placement p;
        const double col = 0.5 * grid.width + 1.5 * (frame - o.motion_frames / 2);
        const double row = 0.5 * grid.height;
        const glm::dvec2 ll = gr.pixel_to_lonlat(col, row);
        p.lon_deg = ll.x, p.lat_deg = ll.y, p.height_m = o.at[2], p.above_ground = true;
        p.heading_deg = 90.0, p.scale = o.scale;
        blockers::SphereBlockers b;
        const glm::dvec2 anchor = render::mesh_anchor(gr, p, o.mesh);
        b.meshes.push_back(blockers::place_spheres(dec.spheres, p, anchor, render::ground_height(grid, anchor), o.mesh));
        b.meshes[0].model_triangles = triangles;  // the sun shadow cast by the triangles, the default
        return b;
    };
    struct Totals {
        double sky_s = 0, sun_s = 0, sun_spheres_s = 0;
        long long pairs = 0, texels = 0;
    };
    Totals tree, flat;
    // The last frame's log-SH of each pass, and its footprint: culling's error is the
    // hierarchy's sky visibility against the flat loop's (every sphere kept).
    std::vector<float> last_log_sh[2];
    visibility::TexelRect last_rect;
    for (int pass = 0; pass < 2; ++pass) {
        const bool use_tree = pass == 0;
        Totals& tot = use_tree ? tree : flat;
        std::vector<float> log_sh = base;
        std::vector<float> sun(texels, 1.0f);
        visibility::TexelRect old_rect;
        for (int f = 0; f < o.motion_frames; ++f) {
            const blockers::SphereBlockers b = place_at(f);
            const double min_sine = blockers::min_cap_sine(b.options.min_solid_angle_sr);
            const visibility::TexelRect rect = visibility::sky_footprint(grid, b.meshes[0], min_sine);
            const Stopwatch t;
            restore(base, log_sh, old_rect, grid.width, texels);
            blockers::SphereBlockers culled = b;
            culled.options.sky_culling = use_tree ? blockers::SphereBlockerOptions::SkyCulling::hierarchy
                                                  : blockers::SphereBlockerOptions::SkyCulling::none;
            const visibility::BlockerStageStats st = visibility::add_blocker_log_sh(
                grid, {0, 0, grid.width, grid.height}, culled, curvature, o.threads, log_sh.data());
            tot.pairs += st.sphere_texel_pairs;
            tot.sky_s += t.seconds();
            tot.texels += rect.texels();
            const visibility::BlockerSunShadow shadow(grid, b, curvature, o.threads);
            const Stopwatch ts;
            std::fill(sun.begin(), sun.end(), 1.0f);
            shadow.apply(o.sun_az, o.sun_el, sun);
            tot.sun_s += ts.seconds();
            blockers::SphereBlockers by_spheres = b;
            by_spheres.options.sun_caster = blockers::SphereBlockerOptions::SunCaster::spheres;
            const visibility::BlockerSunShadow sphere_shadow(grid, by_spheres, curvature, o.threads);
            const Stopwatch tss;
            std::fill(sun.begin(), sun.end(), 1.0f);
            sphere_shadow.apply(o.sun_az, o.sun_el, sun);
            tot.sun_spheres_s += tss.seconds();
            old_rect = rect;
        }
        last_log_sh[pass] = std::move(log_sh);
        last_rect = old_rect;
    }
    const sh::ShVec lobe = visibility::zenith_cosine_lobe();
    double se = 0, worst = 0;
    long long compared = 0;
    for (int r = last_rect.row0; r < last_rect.row1; ++r)
        for (int c = last_rect.col0; c < last_rect.col1; ++c) {
            const std::size_t t = std::size_t(r) * std::size_t(grid.width) + std::size_t(c);
            const double a = visibility::sky_visibility_of_log_sh(last_log_sh[0].data() + t, texels,
                                                                  sh::ExpMethod::scaling_squaring, lobe);
            const double b = visibility::sky_visibility_of_log_sh(last_log_sh[1].data() + t, texels,
                                                                  sh::ExpMethod::scaling_squaring, lobe);
            se += (a - b) * (a - b), worst = std::max(worst, std::abs(a - b)), ++compared;
        }
    const double n = std::max(1, o.motion_frames);
    auto line = [&](const char* what, const Totals& t) {
        std::printf("%-26s %10.1f %10.2f %14.0f %14.3g %14.2f\n", what, 1e3 * t.sky_s / n, 1e3 * t.sun_s / n, t.pairs / n,
                    t.sky_s > 0 ? t.pairs / t.sky_s : 0.0, 1e3 * t.sun_spheres_s / n);
    };
    std::printf("%-26s %10s %10s %14s %14s %14s\n", "per frame", "sky_ms", "sun_ms", "pairs", "pairs_per_s",
                "sun_spheres_ms");
    line("hierarchy (threshold+cull)", tree);
    line("flat (every sphere)", flat);
#ifdef TERRASHADE_HAS_GPU
    run_flat_on_vulkan(grid, place_at(o.motion_frames - 1), curvature, o.threads, last_log_sh[1]);
#endif
    std::printf("footprint %.0f texels a frame; hierarchy / flat sky time: %.3f; sun_ms: cast by the triangles (%d rays "
                "where the spheres shadow, the default), sun_spheres_ms: by the spheres\n", tree.texels / n,
                flat.sky_s > 0 ? tree.sky_s / flat.sky_s : 0.0, blockers::SphereBlockerOptions{}.sun_rays);
    std::printf("culling error: sky visibility rms %.3g, max %.3g over %lld texels (hierarchy against flat, last "
                "frame)\n", compared ? std::sqrt(se / double(compared)) : 0.0, worst, compared);
}

}  // namespace ts::app
