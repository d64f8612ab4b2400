// `terrashade bench sun DEM...`: the per-frame sun visibility, the sweep (SunShadowSweep,
// core/visibility/sun_sweep.hpp) against the exact path (sun_visibility), in the same run:
// ms per frame of each and their ratio, and the sweep's error over a set of sun positions
// from grazing to high: IoU of the shadow masks (fraction < 0.5) and mean |fraction difference|.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "app/io_plan.hpp"
#include "app/bench/bench_command.hpp"
#include "app/bench/csv_number.hpp"
#include "app/bench/error_stats.hpp"
#include "app/dem_input.hpp"
#include "core/terrain/grid_crop.hpp"
#include "core/util/atomic_file.hpp"
#include "core/util/error.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/stopwatch.hpp"
#include "core/visibility/sun_sweep.hpp"
#include "core/visibility/sun_visibility.hpp"
#include "core/visibility/visibility_grid.hpp"
#include "app/options/within_range.hpp"

namespace ts::app {
namespace {

struct BenchSunOptions {
    std::vector<std::string> dems;
    int frames = 5;
    int threads = 2;
    int max_size = 1000;
    std::vector<double> near_fields = {visibility::SunSweepOptions{}.near_field_texels};
    double near_fine = visibility::SunSweepOptions{}.near_field_fine_texels;
    double near_step = visibility::SunSweepOptions{}.near_field_step_texels;
    bool no_curvature = false;
    std::vector<double> elevations = {2, 3, 5, 10, 20, 35, 60};
    std::vector<double> azimuths = {0, 30, 45, 90, 135, 160, 180, 225, 270, 315};
    std::string csv;
};

// One CSV row per DEM, near field and sun elevation (input of scripts/chart_sun.py).
struct CsvRow {
    std::string dem;
    double near_field, elevation, exact_ms, sweep_ms, iou_min, iou_mean, mae_mean;
};

// Shadow masks (fraction < 0.5) and fractions of the sweep against the exact path.
bench::MaskAgreement compare(const std::vector<float>& exact, const std::vector<float>& sweep) {
    bench::MaskAgreement a;
    for (std::size_t i = 0; i < exact.size(); ++i) a.add(exact[i], sweep[i]);
    return a;
}

void run_dem(const BenchSunOptions& o, const std::string& path, double near_field, std::vector<CsvRow>& rows) {
    DemInput in;
    in.files = {path};
    const dem::Dem dem = load_dem_input(in);
    const visibility::VisibilityGrid vgrid(dem);
    const terrain::GridCrop crop = terrain::centre_crop(vgrid.view(), o.max_size, o.max_size);
    const terrain::HeightGrid& grid = crop.grid;

    visibility::SunVisibilityOptions eo;
    eo.curvature = !o.no_curvature;
    eo.threads = o.threads;
    visibility::SunSweepOptions so;
    so.curvature = !o.no_curvature;
    so.threads = o.threads;
    so.near_field_texels = near_field;
    so.near_field_fine_texels = o.near_fine;
    so.near_field_step_texels = o.near_step;
    Stopwatch t0;
    visibility::SunShadowSweep sweep(grid, so);
    const double setup_ms = t0.milliseconds();

    double exact_ms = 0, sweep_ms = 0, iou_min = 2;
    double worst_az = 0, worst_el = 0;
    long worst_exact = 0, worst_sweep = 0;
    long nan_mismatch = 0;
    std::vector<double> all_iou, all_mae;  // one per sun position
    std::vector<float> fast;
    sweep.compute(180.0, 30.0, fast);  // warm-up (first touch), not timed
    std::printf("%s: %dx%d (of %dx%d), sweep setup %.2f ms, near field %.1f texels (1/4 steps to %.1f, then %.2f), %d threads\n",
                std::filesystem::path(path).filename().string().c_str(), grid.width, grid.height, dem.width,
                dem.height, setup_ms, near_field, o.near_fine, o.near_step, thread_count(o.threads));
    std::printf("  %6s %10s %10s %7s %9s %9s %10s\n", "elev", "exact_ms", "sweep_ms", "ratio", "iou_min", "iou_mean",
                "mae_mean");
    for (double el : o.elevations) {
        double e_ms = 0, s_ms = 0;
        std::vector<double> iou, mae;  // one per azimuth
        for (double az : o.azimuths) {
            t0.restart();
            const std::vector<float> exact = visibility::sun_visibility(grid, az, el, eo);
            e_ms += t0.milliseconds();
            t0.restart();
            for (int k = 0; k < o.frames; ++k) sweep.compute(az, el, fast);
            s_ms += t0.milliseconds() / o.frames;
            const bench::MaskAgreement a = compare(exact, fast);
            nan_mismatch += a.nan_mismatch;
            if (a.iou() < iou_min)
                iou_min = a.iou(), worst_az = az, worst_el = el, worst_exact = a.reference_shadow,
                worst_sweep = a.test_shadow;
            iou.push_back(a.iou());
            mae.push_back(a.compared > 0 ? a.mean_abs_difference() : 0.0);  // all void: counts 0
        }
        const double n = double(o.azimuths.size());
        const double imin = bench::min_value(iou), imean = bench::mean(iou), mmean = bench::mean(mae);
        rows.push_back({std::filesystem::path(path).filename().string(), near_field, el, e_ms / n, s_ms / n, imin,
                        imean, mmean});
        std::printf("  %6.1f %10.2f %10.3f %7.1f %9.4f %9.4f %10.5f\n", el, e_ms / n, s_ms / n, e_ms / s_ms, imin,
                    imean, mmean);
        exact_ms += e_ms, sweep_ms += s_ms;
        all_iou.insert(all_iou.end(), iou.begin(), iou.end());
        all_mae.insert(all_mae.end(), mae.begin(), mae.end());
    }
    const int positions = int(all_iou.size());
    std::printf("  all %d sun positions: exact %.2f ms, sweep %.3f ms per frame (%.1fx faster); shadow-mask IoU "
                "mean %.4f, min %.4f (az %.1f, el %.1f: %ld shadowed texels exact, %ld sweep); mean |fraction diff| %.5f (worst position %.5f); "
                "void mismatches %ld\n",
                positions, exact_ms / positions, sweep_ms / positions, exact_ms / sweep_ms, bench::mean(all_iou),
                iou_min, worst_az, worst_el, worst_exact, worst_sweep, bench::mean(all_mae), bench::max_value(all_mae),
                nan_mismatch);
}

}  // namespace

void add_bench_sun_command(CLI::App& bench) {
    auto o = std::make_shared<BenchSunOptions>();
    CLI::App* cmd = bench.add_subcommand(
        "sun", "Per-frame sun visibility: the sweep against the exact path (ms per frame, shadow-mask IoU, mean "
               "|fraction difference|) over sun positions from grazing to high");
    cmd->add_option("DEM", o->dems, "DEM files, each measured on its own")->required();
    cmd->add_option("--frames", o->frames, "Timed sweep frames per sun position (the exact path runs once)")
        ->capture_default_str()
        ->check(within(1, 10000));
    cmd->add_option("--threads", o->threads, "Worker threads of both paths (0 = one per core)")
        ->capture_default_str()
        ->check(within(0, 256));
    cmd->add_option("--max-size", o->max_size, "Measure the central N x N texels of larger DEMs")
        ->capture_default_str()
        ->check(within(1, 100000));
    cmd->add_option("--near-field", o->near_fields,
                    "Sweep: texels marched exactly from each texel centre (a comma list measures each)")
        ->delimiter(',')
        ->capture_default_str()
        ->check(within(0.0, 16.0));
    cmd->add_option("--near-fine", o->near_fine, "Sweep: texels of the near field marched in 1/4-texel steps")
        ->capture_default_str()
        ->check(within(0.0, 16.0));
    cmd->add_option("--near-step", o->near_step, "Sweep: near-field step (texels) beyond the fine part")
        ->capture_default_str()
        ->check(within(0.25, 4.0));
    cmd->add_option("--elevations", o->elevations, "Sun elevations (degrees)")->capture_default_str();
    cmd->add_option("--azimuths", o->azimuths, "Sun azimuths (degrees clockwise from north)")->capture_default_str();
    cmd->add_flag("--no-curvature", o->no_curvature, "Flat Earth (both paths)");
    cmd->add_option("--csv", o->csv, "Write one row per DEM, near field and elevation as CSV (scripts/chart_sun.py)");
    cmd->callback([o] {
        for (double e : o->elevations)
            if (!(e >= -90 && e <= 90)) throw InputError("--elevations: each must be within [-90, 90] degrees");
        IoPlan plan;
        plan.inputs("DEM", o->dems).output("--csv", o->csv, {".csv"});
        plan.check();
        std::vector<CsvRow> rows;
        for (const std::string& path : o->dems)
            for (double near_field : o->near_fields) run_dem(*o, path, near_field, rows);
        if (o->csv.empty()) return;
        write_atomically(o->csv, [&](const std::filesystem::path& tmp) {
            std::ofstream out(tmp);
            out << "dem,near_field,elevation_deg,exact_ms,sweep_ms,iou_min,iou_mean,fraction_mae_mean\n";
            for (const CsvRow& r : rows)
                out << r.dem << ',' << csv_number(r.near_field) << ',' << csv_number(r.elevation) << ','
                    << csv_number(r.exact_ms) << ',' << csv_number(r.sweep_ms) << ',' << csv_number(r.iou_min) << ','
                    << csv_number(r.iou_mean) << ',' << csv_number(r.mae_mean) << '\n';
            if (!out.flush()) throw InputError(o->csv + ": cannot write");
        });
        std::printf("wrote %s\n", o->csv.c_str());
    });
}

}  // namespace ts::app
