// `terrashade bench blockers`: the sphere blockers against the real triangles (ray-traced
// through a BVH, core/visibility/blocker_reference.hpp) for one mesh over a DEM, at sphere
// counts 8 ... 512: the change of sky visibility the mesh makes (RMSE, max error in the sky
// footprint), the sun shadow's IoU with the triangles' and the time of each; then the
// accumulation's throughput and a moving aircraft's per-frame cost (bench_blockers_motion.cpp).
// The figures go to docs/blockers.md, the chart to docs/charts/ (scripts/chart_blockers.py).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "app/bench/bench_blockers.hpp"
#include "app/bench/bench_command.hpp"
#include "app/bench/csv_number.hpp"
#include "app/io_plan.hpp"
#include "core/blockers/sphere_decomposition.hpp"
#include "core/dem/read_dem.hpp"
#include "core/geo/azimuth.hpp"
#include "core/mesh/mesh_import.hpp"
#include "core/render/blocker_sky_clamp.hpp"
#include "core/render/scene_blockers.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/util/angles.hpp"
#include "core/util/atomic_file.hpp"
#include "core/util/error.hpp"
#include "core/util/stopwatch.hpp"
#include "core/visibility/blocker_log_sh.hpp"
#include "core/visibility/blocker_reference.hpp"
#include "core/visibility/blocker_sun_shadow.hpp"
#include "core/visibility/earth_curvature.hpp"
#include "core/visibility/visibility_backend.hpp"

namespace ts::app {
namespace {

struct BlockersRow {
    int count = 0;
    double decompose_s = 0, excess = 0;
    double sky_rmse = 0, sky_max = 0, sky_bias = 0, ref_shadow_mean = 0;
    long long sky_texels = 0, pairs = 0;
    long long shaded_texels = 0;  // where ours or the triangles change the sky by more than 0.01
    double shaded_rmse = 0, ref_dark_max = 0;
    double sky_s = 0;
    double sun_iou = 0, sun_rmse = 0, sun_s = 0;  // cast by the spheres (--mesh-sun-shadow spheres)
    long long sun_ref_texels = 0, sun_ours_texels = 0;
    double tri_iou = 0, tri_rmse = 0, tri_s = 0;  // cast by the triangles where the spheres shadow (the default)
    // The same sky figures without the renderer's bound (render::blocked_sky_term), and the
    // largest brightening the mesh makes there (the bound makes it 0).
    double raw_sky_rmse = 0, raw_shaded_rmse = 0, raw_sky_max = 0, raw_brightening = 0;
};

visibility::TexelRect bounding(const visibility::TexelRect& a, const visibility::TexelRect& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return {std::min(a.col0, b.col0), std::min(a.row0, b.row0), std::max(a.col1, b.col1), std::max(a.row1, b.row1)};
}

// One frame's sun shadow of `b` on an unshadowed field against a reference over `rect`
// (row-major inside it): the masks' IoU (shadow: less than half the disc; NaN when neither has
// one), the RMSE of the visible share, and the frame's time.
struct SunFigures {
    double iou = 0, rmse = 0, seconds = 0;
    long long ref_texels = 0, ours_texels = 0;
};
SunFigures sun_figures(const terrain::HeightGrid& grid, const blockers::SphereBlockers& b, double curvature,
                       int threads, double sun_az, double sun_el, const visibility::TexelRect& rect,
                       const std::vector<float>& ref) {
    SunFigures f;
    std::vector<float> vis(std::size_t(grid.width) * std::size_t(grid.height), 1.0f);
    const visibility::BlockerSunShadow shadow(grid, b, curvature, threads);
    const Stopwatch t;
    shadow.apply(sun_az, sun_el, vis);
    f.seconds = t.seconds();
    const std::size_t w = std::size_t(rect.col1 - rect.col0);
    long long both = 0, either = 0, m = 0;
    double se = 0;
    for (int r = rect.row0; r < rect.row1; ++r)
        for (int c = rect.col0; c < rect.col1; ++c) {
            const float want = ref[std::size_t(r - rect.row0) * w + std::size_t(c - rect.col0)];
            const float ours = vis[std::size_t(r) * std::size_t(grid.width) + std::size_t(c)];
            if (std::isnan(want)) continue;
            const bool a = ours < 0.5f, bb = want < 0.5f;
            both += a && bb, either += a || bb, f.ref_texels += bb, f.ours_texels += a;
            se += double(ours - want) * double(ours - want), ++m;
        }
    f.iou = either ? double(both) / double(either) : NAN;
    f.rmse = m ? std::sqrt(se / double(m)) : 0.0;
    return f;
}

void write_csv(const std::string& path, const std::vector<BlockersRow>& rows) {
    std::ostringstream t;
    t << "spheres,excess_volume_ratio,decompose_s,sky_texels,sky_rmse,sky_max_error,sky_bias,ref_sky_shadow_mean,"
         "shaded_texels,shaded_rmse,ref_sky_shadow_max,sphere_texel_pairs,sky_s,sun_iou,sun_rmse,sun_ref_texels,sun_ours_texels,sun_s,"
         "unbounded_sky_rmse,unbounded_shaded_rmse,unbounded_sky_max_error,unbounded_max_brightening,"
         "triangles_sun_iou,triangles_sun_rmse,triangles_sun_s\n";
    for (const BlockersRow& r : rows)
        t << r.count << ',' << csv_number(r.excess) << ',' << csv_number(r.decompose_s) << ',' << r.sky_texels << ','
          << csv_number(r.sky_rmse) << ',' << csv_number(r.sky_max) << ',' << csv_number(r.sky_bias) << ','
          << csv_number(r.ref_shadow_mean) << ',' << r.shaded_texels << ',' << csv_number(r.shaded_rmse) << ','
          << csv_number(r.ref_dark_max) << ',' << r.pairs << ',' << csv_number(r.sky_s) << ','
          << csv_number(r.sun_iou) << ',' << csv_number(r.sun_rmse) << ',' << r.sun_ref_texels << ','
          << r.sun_ours_texels << ',' << csv_number(r.sun_s) << ',' << csv_number(r.raw_sky_rmse) << ','
          << csv_number(r.raw_shaded_rmse) << ',' << csv_number(r.raw_sky_max) << ',' << csv_number(r.raw_brightening)
          << ',' << csv_number(r.tri_iou) << ',' << csv_number(r.tri_rmse) << ',' << csv_number(r.tri_s) << '\n';
    write_atomically(path, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out << t.str();
        if (!out.flush()) throw input_error(path, "cannot write");
    });
}

void run_bench_blockers(const BenchBlockersOptions& o) {
    blockers::DecompositionOptions check;
    for (int c : o.counts) check.count = c, blockers::validate(check);
    if (o.at.size() != 3) throw InputError("--at takes LON,LAT,HEIGHT_AGL");
    if (o.hpr.size() != 3) throw InputError("--hpr takes H,P,R");
    IoPlan plan;
    plan.input("--dem", o.dem).input("--mesh", o.mesh).output("--csv", o.csv, {".csv"});
    if (o.motion_frames > 0) plan.input("--motion-dem", o.motion_dem);
    plan.check();
    if (o.motion_frames > 0) {
        check.count = o.motion_spheres;
        blockers::validate(check);
    }
    if (o.motion_only) {
        if (o.motion_frames <= 0) throw InputError("bench blockers --motion-only: --motion-frames must be at least 1");
        run_blocker_motion_bench(o);
        return;
    }
    const dem::Dem dem = dem::read_dem(o.dem);
    const terrain::HeightGrid grid = terrain::metric_view(dem);
    const mesh::TriangleMesh mesh = mesh::import_mesh(o.mesh);
    mesh::Placement place;
    place.lon_deg = o.at[0], place.lat_deg = o.at[1], place.height_m = o.at[2], place.above_ground = true;
    place.heading_deg = o.hpr[0], place.pitch_deg = o.hpr[1], place.roll_deg = o.hpr[2], place.scale = o.scale;
    const glm::dvec2 anchor = render::mesh_anchor(dem.georef, place, o.mesh);
    const double ground = render::ground_height(grid, anchor);
    const double curvature = visibility::curvature_factor(true);
    std::printf("bench blockers: %s (%zu triangles, x%.0f, %.0f m agl) over %s (%dx%d), sun az %.0f el %.0f, %d threads\n",
                o.mesh.c_str(), mesh.triangle_count(), o.scale, o.at[2], o.dem.c_str(), grid.width, grid.height,
                o.sun_az, o.sun_el, o.threads);

    // The terrain alone: horizons and log-SH once.
    visibility::VisibilityRequest req;
    req.horizon.directions = o.directions;
    req.horizon.threads = o.threads;
    req.log_sh = true;
    const Stopwatch th;
    const visibility::VisibilityResult base = visibility::make_cpu_visibility_backend()->compute(grid, req);
    std::printf("terrain horizons and log-SH: %.2f s\n", th.seconds());

    // Every count's spheres first: the reference covers the union of their footprints.
    struct Set {
        blockers::SphereDecomposition d;
        blockers::SphereBlockers b;
    };
    std::vector<Set> sets;
    visibility::TexelRect sky_rect, sun_rect;
    const glm::dvec3 sun = geo::enu_direction(geo::azimuth_cw_from_north_to_phi(o.sun_az), radians(o.sun_el));
    for (int c : o.counts) {
        blockers::DecompositionOptions d;
        d.count = c, d.threads = o.threads;
        Set s{blockers::decompose_into_spheres(mesh, d), {}};
        s.b.meshes.push_back(blockers::place_spheres(s.d.spheres, place, anchor, ground, o.mesh));
        if (o.sphere_culling == "hierarchy")
            s.b.options.sky_culling = blockers::SphereBlockerOptions::SkyCulling::hierarchy;
        const double min_sine = blockers::min_cap_sine(s.b.options.min_solid_angle_sr);
        sky_rect = bounding(sky_rect, visibility::sky_footprint(grid, s.b.meshes[0], min_sine));
        const visibility::BlockerSunShadow shadow(grid, s.b, curvature, o.threads);
        sun_rect = bounding(sun_rect, shadow.footprint(0, o.sun_az, o.sun_el));
        sets.push_back(std::move(s));
    }
    const visibility::PlacedTriangles tris = visibility::place_triangles(mesh, place, anchor, ground);
    const std::shared_ptr<const blockers::TriangleBvh> model_triangles = blockers::model_triangle_bvh(mesh);
    visibility::ReferenceOptions ro;
    ro.sky_strata = o.sky_strata, ro.sun_samples = o.sun_samples, ro.threads = o.threads;
    const Stopwatch tr;
    const visibility::SkyReference sky_ref = visibility::reference_sky(grid, base.horizons, tris, sky_rect, curvature, ro);
    const double sky_ref_s = tr.seconds();
    const Stopwatch ts;
    const std::vector<float> sun_ref =
        visibility::reference_sun(grid, tris, sun_rect, sun, blockers::SphereBlockerOptions{}.sun_radius_rad, curvature, ro);
    const double sun_ref_s = ts.seconds();
    std::printf("reference (triangles, BVH): sky %lld texels x %d rays in %.2f s; sun %lld texels x %d rays in %.2f s\n",
                sky_rect.texels(), o.sky_strata * o.sky_strata, sky_ref_s, sun_rect.texels(), o.sun_samples, sun_ref_s);

    const std::size_t texels = base.horizons.texels();
    const sh::ShVec lobe = visibility::zenith_cosine_lobe();
    const sh::ExpMethod exp = sh::ExpMethod::scaling_squaring;  // the renderer's default
    const int sky_w = sky_rect.col1 - sky_rect.col0;
    std::vector<BlockersRow> rows;
    std::printf("%7s %7s %9s %9s %9s %9s %7s %9s %11s %8s %8s %8s %8s %8s %8s %8s | %9s %9s %9s %9s\n", "spheres",
                "excess", "sky_rmse", "sky_max", "sky_bias", "ref_dark", "shaded", "shade_rms", "pairs", "sky_ms",
                "sun_iou", "sun_rmse", "sun_ms", "tri_iou", "tri_rmse", "tri_ms", "ub_rmse", "ub_shade", "ub_max",
                "ub_bright");
    for (const Set& s : sets) {
        BlockersRow row;
        row.count = int(s.d.spheres.size()), row.decompose_s = s.d.seconds, row.excess = s.d.excess_volume_ratio;
        std::vector<float> log_sh(base.log_sh.begin(), base.log_sh.end());
        const Stopwatch t1;
        const visibility::BlockerStageStats st = visibility::add_blocker_log_sh(
            grid, {0, 0, grid.width, grid.height}, s.b, curvature, o.threads, log_sh.data());
        row.sky_s = t1.seconds(), row.pairs = st.sphere_texel_pairs;
        double se = 0, bias = 0, dark = 0, shaded_se = 0, raw_se = 0, raw_shaded_se = 0;
        long long n = 0, raw_shaded = 0;
        for (int r = sky_rect.row0; r < sky_rect.row1; ++r)
            for (int c = sky_rect.col0; c < sky_rect.col1; ++c) {
                const std::size_t t = std::size_t(r) * grid.width + c;
                const std::size_t k = std::size_t(r - sky_rect.row0) * sky_w + std::size_t(c - sky_rect.col0);
                if (std::isnan(sky_ref.terrain[k])) continue;
                const double with = visibility::sky_visibility_of_log_sh(log_sh.data() + t, texels, exp, lobe);
                const double without = visibility::sky_visibility_of_log_sh(base.log_sh.data() + t, texels, exp, lobe);
                const double raw = with - without;
                // As the renderer shades it: bounded by the terrain's own.
                const double ours = render::blocked_sky_term(with, without) - without;
                const double ref = double(sky_ref.with_mesh[k]) - double(sky_ref.terrain[k]);
                const double e = ours - ref, raw_e = raw - ref;
                raw_se += raw_e * raw_e;
                row.raw_sky_max = std::max(row.raw_sky_max, std::abs(raw_e));
                row.raw_brightening = std::max(row.raw_brightening, raw);
                if (std::max(std::abs(raw), std::abs(ref)) > 0.01) raw_shaded_se += raw_e * raw_e, ++raw_shaded;
                se += e * e, bias += e, dark += -ref, ++n;
                row.ref_dark_max = std::max(row.ref_dark_max, -ref);
                if (std::max(std::abs(ours), std::abs(ref)) > 0.01) shaded_se += e * e, ++row.shaded_texels;
                row.sky_max = std::max(row.sky_max, std::abs(e));
            }
        row.sky_texels = n;
        row.shaded_rmse = row.shaded_texels ? std::sqrt(shaded_se / double(row.shaded_texels)) : 0.0;
        row.raw_sky_rmse = n ? std::sqrt(raw_se / n) : 0.0;
        row.raw_shaded_rmse = raw_shaded ? std::sqrt(raw_shaded_se / double(raw_shaded)) : 0.0;
        row.sky_rmse = n ? std::sqrt(se / n) : 0.0, row.sky_bias = n ? bias / n : 0.0, row.ref_shadow_mean = n ? dark / n : 0.0;

        // The sun shadow cast by the spheres, then by the triangles where the spheres shadow.
        blockers::SphereBlockers by_spheres = s.b, by_triangles = s.b;
        by_spheres.options.sun_caster = blockers::SphereBlockerOptions::SunCaster::spheres;
        by_triangles.options.sun_caster = blockers::SphereBlockerOptions::SunCaster::triangles;
        by_triangles.meshes[0].model_triangles = model_triangles;
        const SunFigures fs = sun_figures(grid, by_spheres, curvature, o.threads, o.sun_az, o.sun_el, sun_rect, sun_ref);
        const SunFigures ft = sun_figures(grid, by_triangles, curvature, o.threads, o.sun_az, o.sun_el, sun_rect, sun_ref);
        row.sun_iou = fs.iou, row.sun_rmse = fs.rmse, row.sun_s = fs.seconds;
        row.sun_ref_texels = fs.ref_texels, row.sun_ours_texels = fs.ours_texels;
        row.tri_iou = ft.iou, row.tri_rmse = ft.rmse, row.tri_s = ft.seconds;
        std::printf("%7d %7.2f %9.4f %9.4f %+9.4f %9.4f %7lld %9.4f %11lld %8.1f %8.3f %8.4f %8.2f %8.3f %8.4f %8.2f | "
                    "%9.4f %9.4f %9.4f %9.4f\n",
                    row.count, row.excess, row.sky_rmse, row.sky_max, row.sky_bias, row.ref_shadow_mean,
                    row.shaded_texels, row.shaded_rmse, row.pairs, 1e3 * row.sky_s, row.sun_iou, row.sun_rmse,
                    1e3 * row.sun_s, row.tri_iou, row.tri_rmse, 1e3 * row.tri_s, row.raw_sky_rmse, row.raw_shaded_rmse, row.raw_sky_max, row.raw_brightening);
        std::fflush(stdout);
        rows.push_back(row);
    }
    std::printf("sky: error of the sky-visibility change the mesh makes (ours - triangles) over the %lld texels of the sky "
                "footprint; ref_dark: the triangles' mean darkening there (largest %.3f); shaded, shade_rms: the texels "
                "either changes by more than 0.01 and the RMSE over them. sun: shadow = less than half the disc, %lld "
                "texels of the triangles'; sun_*: cast by the spheres (--mesh-sun-shadow spheres), tri_*: by the "
                "triangles where the spheres shadow, %d rays over the disc (the default). ours is bounded by the terrain's own sky per texel as the renderer shades it "
                "(render::blocked_sky_term); ub_*: the same without the bound, ub_bright the largest brightening the "
                "mesh makes\n",
                rows.empty() ? 0 : rows[0].sky_texels, rows.empty() ? 0.0 : rows[0].ref_dark_max,
                rows.empty() ? 0 : rows[0].sun_ref_texels, blockers::SphereBlockerOptions{}.sun_rays);
    if (!o.csv.empty()) write_csv(o.csv, rows);

    // The sun caster's knobs at 64 spheres (or the count nearest it): the spheres, and the
    // triangles at 4 ... 64 rays over the disc, against a reference of 4 x the most rays.
    if (!sets.empty()) {
        const Set* at64 = &sets[0];
        for (const Set& s : sets)
            if (std::abs(int(s.d.spheres.size()) - 64) < std::abs(int(at64->d.spheres.size()) - 64)) at64 = &s;
        visibility::ReferenceOptions fine = ro;
        fine.sun_samples = 256;
        const std::vector<float> sun_fine = visibility::reference_sun(
            grid, tris, sun_rect, sun, blockers::SphereBlockerOptions{}.sun_radius_rad, curvature, fine);
        std::printf("sun caster at %zu spheres against %d rays over the disc through the triangles (%lld texels):\n",
                    at64->d.spheres.size(), fine.sun_samples, sun_rect.texels());
        auto measure = [&](blockers::SphereBlockerOptions::SunCaster caster, int rays) {
            blockers::SphereBlockers b = at64->b;
            b.options.sun_caster = caster, b.options.sun_rays = rays;
            b.meshes[0].model_triangles = model_triangles;
            const SunFigures f = sun_figures(grid, b, curvature, o.threads, o.sun_az, o.sun_el, sun_rect, sun_fine);
            const bool spheres = caster == blockers::SphereBlockerOptions::SunCaster::spheres;
            const bool is_default = !spheres && rays == blockers::SphereBlockerOptions{}.sun_rays;
            char what[64];
            std::snprintf(what, sizeof what, spheres ? "spheres" : "triangles %d rays", rays);
            std::printf("sun caster %-20s ms %8.3f rmse %.5f iou %.4f%s\n", what, 1e3 * f.seconds, f.rmse, f.iou,
                        is_default ? "  (default)" : "");
        };
        measure(blockers::SphereBlockerOptions::SunCaster::spheres, 0);
        for (int rays : {4, 8, 16, 32, 64}) measure(blockers::SphereBlockerOptions::SunCaster::triangles, rays);
    }
    std::vector<blockers::SphereDecomposition> decompositions;
    for (const Set& s : sets) decompositions.push_back(s.d);
    run_blocker_self_bench(mesh, decompositions, o.threads);
    if (o.motion_frames > 0) run_blocker_motion_bench(o);
}

}  // namespace

void add_bench_blockers_command(CLI::App& bench) {
    auto o = std::make_shared<BenchBlockersOptions>();
    CLI::App* cmd = bench.add_subcommand(
        "blockers", "Mesh blockers vs the ray-traced triangles (sky, sun) at sphere counts 8..512; throughput; moving aircraft");
    cmd->add_option("--dem", o->dem, "DEM under the mesh")->capture_default_str();
    cmd->add_option("--mesh", o->mesh, "Mesh file")->capture_default_str();
    cmd->add_option("--at", o->at, "LON,LAT,HEIGHT_AGL of the mesh")->delimiter(',')->capture_default_str();
    cmd->add_option("--hpr", o->hpr, "Heading, pitch, roll, degrees")->delimiter(',')->capture_default_str();
    cmd->add_option("--scale", o->scale, "Mesh scale")->capture_default_str();
    cmd->add_option("--sun-az", o->sun_az, "Sun azimuth, degrees clockwise from north")->capture_default_str();
    cmd->add_option("--sun-el", o->sun_el, "Sun elevation, degrees")->capture_default_str();
    cmd->add_option("--counts", o->counts, "Sphere counts")->delimiter(',');
    cmd->add_option("--directions", o->directions, "Terrain horizon directions")->capture_default_str();
    cmd->add_option("--sky-strata", o->sky_strata, "Reference sky rays per texel: strata^2")->capture_default_str();
    cmd->add_option("--sun-samples", o->sun_samples, "Reference rays per texel over the sun's disc")->capture_default_str();
    cmd->add_option("--threads", o->threads, "Worker threads")->capture_default_str();
    cmd->add_option("--sphere-culling", o->sphere_culling,
                    "Accuracy part: hierarchy or none (as render --sphere-culling; the moving aircraft runs both)")
        ->capture_default_str()
        ->check(CLI::IsMember({"hierarchy", "none"}));
    cmd->add_option("--csv", o->csv, "Also write the accuracy rows as CSV");
    cmd->add_option("--motion-dem", o->motion_dem, "DEM of the moving-aircraft run")->capture_default_str();
    cmd->add_option("--motion-spheres", o->motion_spheres, "Spheres of the moving aircraft")->capture_default_str();
    cmd->add_flag("--motion-only", o->motion_only, "Only the moving aircraft (no accuracy against the triangles)");
    cmd->add_option("--motion-frames", o->motion_frames, "Frames of the moving-aircraft run (0: skip it)")
        ->capture_default_str();
    cmd->callback([o] { run_bench_blockers(*o); });
}

}  // namespace ts::app
