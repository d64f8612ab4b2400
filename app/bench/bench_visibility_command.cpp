// `terrashade bench visibility`: accuracy and speed of the horizon methods on real DEMs,
// against the raymarch reference, and (with --saga) SAGA's sky view factor on the same
// projected DEM in the same run. Its CSV feeds scripts/chart_visibility.py.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <span>
#include <string>
#include <vector>

#include "app/io_plan.hpp"
#include "app/bench/bench_command.hpp"
#include "app/bench/csv_number.hpp"
#include "app/bench/error_stats.hpp"
#include "app/bench/shell_command.hpp"
#include "app/compute_device.hpp"
#include "core/dem/read_dem.hpp"
#include "core/raster/raster_writer.hpp"
#include "core/util/angles.hpp"
#include "core/util/atomic_file.hpp"
#include "core/util/error.hpp"
#include "core/util/stopwatch.hpp"
#include "core/quality/visibility_quality.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/sky_integrals.hpp"
#include "core/visibility/horizon_sh.hpp"
#include "core/visibility/visibility_grid.hpp"
#include "core/visibility/visibility_products.hpp"
#include "app/options/within_range.hpp"

namespace ts::app {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct BenchVisibilityOptions {
    std::vector<std::string> dems;
    int window = 300;
    std::vector<int> directions = {8, 16, 32, 64};
    std::vector<std::string> methods = {"exact", "pyramid", "raymarch"};
    std::vector<std::string> schedules = {"balanced"};
    // exact variants "near:lines": near field in texels and sweep lines per texel.
    std::vector<std::string> exact_variants = {"2:1"};
    int reference_directions = 256;
    int full_directions = 32;
    bool full = false;
    bool whole = false;  // --whole: the whole DEM on the GPU, the CPU and SAGA, stage by stage
    std::string whole_method = "exact";  // --whole-method: exact or pyramid (both run on the GPU)
    int repeats = 3;
    bool no_saga = false;
    std::optional<std::uint32_t> device;
    bool no_curvature = false;
    bool exact_scalar = false;  // --exact-scalar: HorizonOptions::exact_simd_lines off
    bool saga = false;
    int threads = 0;
    std::string csv;
};

struct Row {
    std::string dem, method, variant;
    int width = 0, height = 0, directions = 0;
    double time_ms = kNaN;
    double horizon_rmse_deg = kNaN, horizon_p99_deg = kNaN;
    double svf_rmse = kNaN, svf_p99 = kNaN, svf_rmse_constant = kNaN;
    double sky_rmse = kNaN, sky_p99 = kNaN;
    double saga_visible_rmse = kNaN, saga_svf_rmse = kNaN;  // in SAGA's definitions (see docs/visibility.md)
    double mean_tan_slope = kNaN;  // of the window (quality::mean_tan_slope: what --max-error predicts from)
};

// Absolute errors (RMSE, 99th percentile) over the interior texels (the outermost ring has no
// terrain beyond it in some directions; its horizon is a convention) where both rasters are valid.
bench::AbsoluteErrors compare(const std::vector<float>& a, const std::vector<float>& b, int w, int h) {
    std::vector<double> err;
    for (int r = 1; r + 1 < h; ++r)
        for (int c = 1; c + 1 < w; ++c) {
            const std::size_t i = std::size_t(r) * w + c;
            if (std::isnan(a[i]) || std::isnan(b[i])) continue;
            err.push_back(std::abs(double(a[i]) - b[i]));
        }
    return bench::absolute_errors(std::move(err));
}

// The same for horizon angles in degrees, the D planes of `set` against the planes of `ref`
// at the same azimuths, stacked as one sample.
bench::AbsoluteErrors compare_horizons(const visibility::HorizonSet& ref, const visibility::HorizonSet& set) {
    const int step = ref.directions / set.directions;
    std::vector<double> err;
    for (int d = 0; d < set.directions; ++d) {
        const float* pr = ref.plane(d * step);
        const float* ps = set.plane(d);
        for (int r = 1; r + 1 < set.height; ++r)
            for (int c = 1; c + 1 < set.width; ++c) {
                const std::size_t i = std::size_t(r) * set.width + c;
                if (std::isnan(pr[i]) || std::isnan(ps[i])) continue;
                err.push_back(std::abs(double(pr[i]) - ps[i]) * 180.0 / kPi);
            }
    }
    return bench::absolute_errors(std::move(err));
}

// A centred window of at most n x n texels (the raymarch reference is slow).
dem::Dem centre_window(const dem::Dem& d, int n) {
    const int w = std::min(n, d.width), h = std::min(n, d.height);
    const int c0 = (d.width - w) / 2, r0 = (d.height - h) / 2;
    if (w == d.width && h == d.height) return d;
    dem::Dem out;
    out.width = w;
    out.height = h;
    out.z.resize(std::size_t(w) * h);
    out.void_mask.resize(out.z.size());
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            out.z[std::size_t(r) * w + c] = d.at(c0 + c, r0 + r);
            out.void_mask[std::size_t(r) * w + c] = d.void_mask.empty() ? 0 : d.void_mask[d.index(c0 + c, r0 + r)];
        }
    out.georef = d.georef.window(c0, r0, w, h);
    out.vertical_datum = d.vertical_datum;
    out.source = d.source;
    return out;
}

// SAGA's outputs (ta_lighting 3, view_shed.cpp) from horizons with constant sectors:
// Visible = mean(1 - H / 90 deg) (linear in angle, not a solid angle), and
// SVF = mean(cos(s) cos^2 H + sin(s) cos(phi - aspect) (pi/2 - H - sin H cos H)) for a receiver
// tilted by slope s (H >= 0: SAGA starts every search at 0).
struct SagaQuantities {
    std::vector<float> visible, svf;
};
SagaQuantities saga_quantities(const visibility::HorizonSet& set, const terrain::HeightGrid& g) {
    SagaQuantities q;
    q.visible.assign(set.texels(), std::numeric_limits<float>::quiet_NaN());
    q.svf = q.visible;
    for (int r = 1; r + 1 < set.height; ++r)
        for (int c = 1; c + 1 < set.width; ++c) {
            const std::size_t i = std::size_t(r) * set.width + c;
            // Slope and downhill aspect (clockwise from north) from central differences, as SAGA's
            // Get_Gradient (Zevenbergen and Thorne).
            const double dzdx = (g.at(c + 1, r) - g.at(c - 1, r)) / (2 * g.dx_m[std::size_t(r)]);
            const double dzdy = (g.at(c, r - 1) - g.at(c, r + 1)) / (2 * g.dy_m[std::size_t(r)]);
            if (std::isnan(dzdx) || std::isnan(dzdy) || std::isnan(set.plane(0)[i])) continue;
            const double slope = std::atan(std::hypot(dzdx, dzdy));
            const double aspect = std::atan2(-dzdx, -dzdy);
            double vis = 0, svf = 0;
            for (int d = 0; d < set.directions; ++d) {
                const double hz = std::max(0.0, double(set.plane(d)[i]));
                const double az = visibility::user_azimuth_deg(d, set.directions) * kPi / 180.0;
                vis += 1.0 - hz / (kPi / 2);
                svf += std::cos(slope) * std::cos(hz) * std::cos(hz) +
                       std::sin(slope) * std::cos(az - aspect) * (kPi / 2 - hz - std::sin(hz) * std::cos(hz));
            }
            q.visible[i] = float(vis / set.directions);
            q.svf[i] = float(svf / set.directions);
        }
    return q;
}

// "near,lines" -> the exact method's near field (texels) and sweep lines per texel.
void set_exact_variant(visibility::HorizonOptions& ho, const std::string& variant) {
    double near = 0;
    int lines = 0;
    if (std::sscanf(variant.c_str(), "%lf:%d", &near, &lines) != 2 || near < 0 || lines < 1 || lines > 4)
        throw InputError("--exact-variants: expected NEAR:LINES such as 2:1, got '" + variant + "'");
    ho.exact_near_field_texels = near;
    ho.exact_lines_per_texel = lines;
}

void print_row(const Row& r) {
    std::printf("%-28s %-14s %-9s %4d %9.1f %9.3f %9.3f %9.5f %9.5f %9.5f %9.5f %9.5f %9.5f\n", r.dem.c_str(),
                r.method.c_str(), r.variant.c_str(), r.directions, r.time_ms, r.horizon_rmse_deg, r.horizon_p99_deg,
                r.svf_rmse, r.svf_p99, r.svf_rmse_constant, r.sky_rmse, r.saga_visible_rmse, r.saga_svf_rmse);
    std::fflush(stdout);
}

void run_saga(const BenchVisibilityOptions& o, const dem::Dem& win, const terrain::HeightGrid& grid,
              const visibility::HorizonSet& ref, std::vector<Row>& rows, const std::string& name) {
    if (win.georef.crs().is_geographic())
        throw input_error(win.source,
                          "--saga needs a projected DEM (SAGA takes cell sizes in map units); "
                          "reproject it first, e.g. scripts/bench_visibility.sh does with gdalwarp");
    const auto dir = std::filesystem::temp_directory_path() / ("terrashade-bench-saga-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string in = (dir / "dem.tif").string();
    std::vector<float> z(grid.z.begin(), grid.z.end());
    raster::write_float_raster(in, win.width, win.height, 1, z.data(), win.georef);
    const SagaQuantities ref_q = saga_quantities(ref, grid);
    const double radius = 2.0 * std::hypot(win.width * grid.dx_m[0], win.height * grid.dy_m[0]);
    for (int d : o.directions) {
        for (int method : {0, 1}) {
            const std::string vis = (dir / "visible.tif").string(), svf = (dir / "svf.tif").string();
            std::filesystem::remove(vis);
            std::filesystem::remove(svf);
            const std::string cmd = "saga_cmd ta_lighting 3 -DEM '" + in + "' -VISIBLE '" + vis + "' -SVF '" + svf +
                                    "' -NDIRS " + std::to_string(d) + " -RADIUS " + std::to_string(radius) +
                                    " -METHOD " + std::to_string(method) + " > '" + (dir / "saga.log").string() +
                                    "' 2>&1";
            const Stopwatch t0;
            const int rc = std::system(cmd.c_str());
            const double ms = t0.milliseconds();
            if (rc != 0 || !std::filesystem::exists(svf))
                throw InputError("saga_cmd failed (exit " + std::to_string(rc) + "); see " +
                                 (dir / "saga.log").string());
            const dem::Dem sv = dem::read_dem(vis), sf = dem::read_dem(svf);
            std::vector<float> v(sv.z), f(sf.z);
            for (auto& x : v) x /= 100.0f;  // SAGA's Visible is in percent
            Row r;
            r.dem = name;
            r.method = method == 0 ? "saga-cellsize" : "saga-multiscale";
            r.variant = "saga";
            r.width = win.width;
            r.height = win.height;
            r.directions = d;
            r.time_ms = ms;
            r.saga_visible_rmse = compare(v, ref_q.visible, win.width, win.height).rmse;
            r.saga_svf_rmse = compare(f, ref_q.svf, win.width, win.height).rmse;
            rows.push_back(r);
            print_row(r);
        }
        // terrashade's exact horizons at the same sector count, in SAGA's formulas.
        visibility::HorizonOptions ho;
        ho.directions = d;
        ho.curvature = !o.no_curvature;
        ho.threads = o.threads;
        const Stopwatch t0;
        const visibility::HorizonSet set = visibility::compute_horizons(grid, ho);
        const SagaQuantities q = saga_quantities(set, grid);
        Row r;
        r.dem = name;
        r.method = "exact";
        r.variant = "saga-formula";
        r.width = win.width;
        r.height = win.height;
        r.directions = d;
        r.time_ms = t0.milliseconds();
        r.saga_visible_rmse = compare(q.visible, ref_q.visible, win.width, win.height).rmse;
        r.saga_svf_rmse = compare(q.svf, ref_q.svf, win.width, win.height).rmse;
        rows.push_back(r);
        print_row(r);
    }
    std::filesystem::remove_all(dir);
}

void write_csv(const BenchVisibilityOptions& o, const std::vector<Row>& rows) {
    if (o.csv.empty()) return;
    {
        std::ostringstream csv;
        csv << "dem,method,variant,width,height,directions,reference_directions,curvature,time_ms,"
               "horizon_rmse_deg,horizon_p99_deg,svf_rmse,svf_p99,svf_rmse_constant,sky_rmse,sky_p99,"
               "saga_visible_rmse,saga_svf_rmse,mean_tan_slope\n";
        for (const Row& r : rows)
            csv << r.dem << ',' << r.method << ',' << r.variant << ',' << r.width << ',' << r.height << ','
                << r.directions << ',' << o.reference_directions << ',' << (o.no_curvature ? 0 : 1) << ','
                << csv_number(r.time_ms) << ',' << csv_number(r.horizon_rmse_deg) << ',' << csv_number(r.horizon_p99_deg) << ','
                << csv_number(r.svf_rmse) << ',' << csv_number(r.svf_p99) << ',' << csv_number(r.svf_rmse_constant) << ',' << csv_number(r.sky_rmse)
                << ',' << csv_number(r.sky_p99) << ',' << csv_number(r.saga_visible_rmse) << ',' << csv_number(r.saga_svf_rmse) << ',' << csv_number(r.mean_tan_slope) << '\n';
        write_atomically(o.csv, [&](const std::filesystem::path& tmp) {
            std::ofstream out(tmp, std::ios::binary);
            out << csv.str();
            if (!out.flush()) throw input_error(o.csv, "cannot write");
        });
    }
}


// ---- --whole: the whole DEM, GPU and CPU stage by stage, and SAGA on a UTM copy ----

// Timings are the median of a few runs (bench::median): the machine is shared, one run can be
// 2x another.
using bench::median;

// svf RMSE of `svf` (whole-grid layout) against `ref` (the window's layout), interior of the window.
double window_svf_rmse(std::span<const float> svf, int grid_w, const visibility::ReceiverWindow& w,
                       const std::vector<float>& ref) {
    std::vector<float> part(std::size_t(w.width) * std::size_t(w.height));
    for (int r = 0; r < w.height; ++r)
        for (int c = 0; c < w.width; ++c)
            part[std::size_t(r) * w.width + c] = svf[std::size_t(w.row0 + r) * grid_w + std::size_t(w.col0 + c)];
    return compare(part, ref, w.width, w.height).rmse;
}

visibility::ReceiverWindow centred(int width, int height, int n) {
    const int w = std::min(n, width), h = std::min(n, height);
    return {(width - w) / 2, (height - h) / 2, w, h};
}

// SAGA quantities (saga_quantities) of a set computed on a window of `g`, from the window's
// texels of g: the set covers the window only.
SagaQuantities saga_quantities_window(const visibility::HorizonSet& set, const terrain::HeightGrid& g,
                                      const visibility::ReceiverWindow& w) {
    std::vector<float> z(std::size_t(w.width) * std::size_t(w.height));
    for (int r = 0; r < w.height; ++r)
        for (int c = 0; c < w.width; ++c) z[std::size_t(r) * w.width + c] = g.at(w.col0 + c, w.row0 + r);
    terrain::HeightGrid sub;
    sub.width = w.width;
    sub.height = w.height;
    sub.z = z;
    sub.dx_m.assign(g.dx_m.begin() + w.row0, g.dx_m.begin() + w.row0 + w.height);
    sub.dy_m.assign(g.dy_m.begin() + w.row0, g.dy_m.begin() + w.row0 + w.height);
    return saga_quantities(set, sub);
}

void run_whole(const BenchVisibilityOptions& o, const std::string& path) {
    const dem::Dem dem = dem::read_dem(path);
    const std::string name = std::filesystem::path(path).filename().string();
    const visibility::VisibilityGrid grid(dem);
    const int D = o.full_directions;
    const double texel_azimuths = double(dem.width) * dem.height * D;
    visibility::HorizonOptions ho;
    ho.directions = D;
    ho.curvature = !o.no_curvature;
    ho.threads = o.threads;
    ho.method = *visibility::parse_method(o.whole_method);
    ho.exact_simd_lines = !o.exact_scalar;
    std::printf("%s: %dx%d texels, D = %d, %s horizons -> svf, sky_visible, log-SH; median of %d runs "
                "(wall ms; the machine is shared, compare rows of one run)\n",
                name.c_str(), dem.width, dem.height, D, o.whole_method.c_str(), o.repeats);

    // The reference: raymarch horizons of a centred window, blockers from the whole grid.
    const visibility::ReceiverWindow win = centred(dem.width, dem.height, o.window);
    visibility::HorizonOptions ref_opts = ho;
    ref_opts.method = visibility::HorizonMethod::raymarch;
    ref_opts.directions = o.reference_directions;
    ref_opts.window = win;
    Stopwatch t0;
    const visibility::HorizonSet ref = visibility::compute_horizons(grid.view(), ref_opts);
    const auto svf_ref = visibility::svf_raster(ref, visibility::WedgeRule::linear, o.threads);
    std::printf("  reference: raymarch D=%d on the centred %dx%d window, %.0f ms\n", o.reference_directions,
                win.width, win.height, t0.milliseconds());

    // Each path as the visibility command runs it (the backend seam): the default (--device
    // auto), the CPU and the Vulkan device, stage by stage.
    visibility::VisibilityRequest request;
    request.horizon = ho;
    request.log_sh = request.svf = request.sky_visible = true;
    struct PathRun {
        std::string label;
        double ms = kNaN;
    };
    std::vector<PathRun> runs;
    auto run_path = [&](const std::string& label, const DeviceArgs& args) {
        std::unique_ptr<ComputeDevice> device;
        try {
            device = std::make_unique<ComputeDevice>(args);
        } catch (const InputError& e) {
            if (o.device) throw;
            std::printf("  %-7s not run: %s\n", label.c_str(), e.what());
            return;
        }
        std::vector<double> total;
        std::vector<std::vector<double>> stage_s;
        visibility::VisibilityResult last;
        for (int rep = 0; rep < o.repeats; ++rep) {
            t0.restart();
            last = device->visibility().compute(grid.view(), request);
            total.push_back(t0.milliseconds());
            for (std::size_t i = 0; i < last.stages.size(); ++i) {
                if (stage_s.size() <= i) stage_s.emplace_back();
                stage_s[i].push_back(last.stages[i].seconds * 1e3);
            }
        }
        const double ms = median(total);
        std::string stage_text;
        for (std::size_t i = 0; i < stage_s.size(); ++i)
            stage_text += (i ? "; " : "") + last.stages[i].label + " " +
                          std::to_string(int(std::lround(median(stage_s[i])))) + " on " + last.stages[i].path;
        std::printf("  %-7s %9.0f ms  (%s)  %.3g texel-azimuths/s  svf RMSE %.5f\n", label.c_str(), ms,
                    stage_text.c_str(), texel_azimuths / (ms / 1000), window_svf_rmse(last.svf, dem.width, win, svf_ref));
        runs.push_back({label, ms});
    };
    DeviceArgs default_args, cpu_args, vulkan_args;
    cpu_args.device = "cpu";
    vulkan_args.device = o.device ? std::to_string(*o.device) : "vulkan";
    const DeviceChoice choice = choose_device(default_args);
    std::printf("  default path: %s\n", choice.reason.c_str());
    run_path("default", default_args);
    run_path("cpu", cpu_args);
#ifdef TERRASHADE_HAS_GPU
    run_path("vulkan", vulkan_args);
#endif
    double fastest = kNaN;
    for (const auto& r : runs)
        if (r.label != "default" && !(r.ms >= fastest)) fastest = r.ms;
    if (!runs.empty() && runs[0].label == "default")
        std::printf("  default / fastest path time: %.2f\n", runs[0].ms / fastest);

    if (o.no_saga) return;
    if (!on_path("saga_cmd") || !on_path("gdalwarp")) {
        std::printf("  saga not run: saga_cmd or gdalwarp is not installed\n");
        return;
    }
    // SAGA as a user would run it: the DEM reprojected to its UTM zone at ~92 m, then
    // ta_lighting 3 with its defaults (10 km radius, cell-size method) and D sectors.
    const auto dir = std::filesystem::temp_directory_path() / ("terrashade-bench-whole-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const glm::dvec2 centre = dem.georef.pixel_to_lonlat(dem.width * 0.5, dem.height * 0.5);
    const int zone = std::clamp(int(std::floor((centre.x + 180.0) / 6.0)) + 1, 1, 60);
    const std::string epsg = "EPSG:" + std::to_string((centre.y >= 0 ? 32600 : 32700) + zone);
    const std::string utm = (dir / "utm.tif").string(), svf = (dir / "svf.tif").string(),
                      vis = (dir / "visible.tif").string(), log = (dir / "saga.log").string();
    const std::string warp = "gdalwarp -q -overwrite -t_srs " + epsg + " -tr 92 92 -r bilinear '" + path + "' '" + utm +
                             "' > '" + log + "' 2>&1";
    if (std::system(warp.c_str()) != 0) throw InputError("gdalwarp failed; see " + log);
    const dem::Dem udem = dem::read_dem(utm);
    const std::string saga = "saga_cmd ta_lighting 3 -DEM '" + utm + "' -VISIBLE '" + vis + "' -SVF '" + svf +
                             "' -NDIRS " + std::to_string(D) + " > '" + log + "' 2>&1";
    std::vector<double> saga_times;
    for (int rep = 0; rep < o.repeats; ++rep) {
        std::filesystem::remove(svf);
        t0.restart();
        const int rc = std::system(saga.c_str());
        saga_times.push_back(t0.milliseconds());
        if (rc != 0 || !std::filesystem::exists(svf)) throw InputError("saga_cmd failed; see " + log);
    }
    const double saga_ms = median(saga_times);
    // Errors in SAGA's own formulas (see docs/visibility.md), against the raymarch horizons of a
    // centred window of the UTM copy (blockers from the whole copy, flat Earth as SAGA).
    const visibility::VisibilityGrid ugrid(udem);
    const visibility::ReceiverWindow uwin = centred(udem.width, udem.height, o.window);
    visibility::HorizonOptions uref = ref_opts;
    uref.window = uwin;
    uref.curvature = false;
    const auto uref_set = visibility::compute_horizons(ugrid.view(), uref);
    const SagaQuantities ref_q = saga_quantities_window(uref_set, ugrid.view(), uwin);
    const dem::Dem saga_vis = dem::read_dem(vis), saga_svf = dem::read_dem(svf);
    std::vector<float> sv(std::size_t(uwin.width) * uwin.height), ss(sv.size());
    for (int r = 0; r < uwin.height; ++r)
        for (int c = 0; c < uwin.width; ++c) {
            sv[std::size_t(r) * uwin.width + c] = saga_vis.at(uwin.col0 + c, uwin.row0 + r) / 100.0f;
            ss[std::size_t(r) * uwin.width + c] = saga_svf.at(uwin.col0 + c, uwin.row0 + r);
        }
    visibility::HorizonOptions ours = ho;
    ours.window = uwin;
    ours.curvature = false;
    const SagaQuantities our_q =
        saga_quantities_window(visibility::compute_horizons(ugrid.view(), ours), ugrid.view(), uwin);
    std::printf("  saga %9.0f ms  (saga_cmd ta_lighting 3, defaults, %d sectors, on %s %dx%d at 92 m)  %.3g "
                "texel-azimuths/s\n",
                saga_ms, D, epsg.c_str(), udem.width, udem.height,
                double(udem.width) * udem.height * D / (saga_ms / 1000));
    std::printf("  in SAGA's formulas on the UTM window: SVF RMSE saga %.5f, terrashade exact %.5f; Visible RMSE "
                "saga %.5f, terrashade exact %.5f\n",
                compare(ss, ref_q.svf, uwin.width, uwin.height).rmse,
                compare(our_q.svf, ref_q.svf, uwin.width, uwin.height).rmse,
                compare(sv, ref_q.visible, uwin.width, uwin.height).rmse,
                compare(our_q.visible, ref_q.visible, uwin.width, uwin.height).rmse);
    std::printf("  saga time /");
    for (std::size_t i = 0; i < runs.size(); ++i)
        std::printf("%s %s time: %.2f", i ? "," : "", runs[i].label.c_str(), saga_ms / runs[i].ms);
    std::printf("\n");
    std::filesystem::remove_all(dir);
}

void run_bench_visibility(const BenchVisibilityOptions& o) {
    IoPlan plan;
    plan.inputs("DEM", o.dems).output("--csv", o.csv, {".csv"});
    plan.check();
    if (o.whole) {
        if (o.reference_directions % o.full_directions != 0)
            throw InputError("--full-directions must divide --reference-directions");
        for (const auto& path : o.dems) run_whole(o, path);
        return;
    }
    for (int d : o.directions)
        if (d < 1 || o.reference_directions % d != 0)
            throw InputError("--directions: each count must divide --reference-directions (" +
                             std::to_string(o.reference_directions) + "), got " + std::to_string(d));
    for (const auto& m : o.methods)
        if (!visibility::parse_method(m)) throw InputError("--methods: unknown method '" + m + "'");
    std::vector<Row> rows;
    std::printf("%-28s %-14s %-9s %4s %9s %9s %9s %9s %9s %9s %9s %9s %9s\n", "dem", "method", "variant", "D", "ms",
                "hz_rms", "hz_p99", "svf_rmse", "svf_p99", "svf_cst", "sky_rmse", "saga_vis", "saga_svf");
    for (const auto& path : o.dems) {
        const dem::Dem full = dem::read_dem(path);
        const std::string name = std::filesystem::path(path).filename().string();
        const dem::Dem win = centre_window(full, o.window);
        const visibility::VisibilityGrid grid(win);
        const double roughness = quality::mean_tan_slope(grid.view());

        visibility::HorizonOptions ref_opts;
        ref_opts.method = visibility::HorizonMethod::raymarch;
        ref_opts.directions = o.reference_directions;
        ref_opts.curvature = !o.no_curvature;
        ref_opts.threads = o.threads;
        Stopwatch t0;
        const visibility::HorizonSet ref = visibility::compute_horizons(grid.view(), ref_opts);
        Row ref_row;
        ref_row.dem = name;
        ref_row.method = "reference";
        ref_row.variant = "raymarch";
        ref_row.width = win.width;
        ref_row.height = win.height;
        ref_row.directions = o.reference_directions;
        ref_row.time_ms = t0.milliseconds();
        rows.push_back(ref_row);
        print_row(ref_row);
        const auto svf_ref = visibility::svf_raster(ref, visibility::WedgeRule::linear, o.threads);
        const auto sky_ref = visibility::sky_visible_raster(ref, visibility::WedgeRule::linear, o.threads);

        for (const auto& m : o.methods) {
            const auto method = *visibility::parse_method(m);
            const std::vector<std::string> variants = method == visibility::HorizonMethod::pyramid ? o.schedules
                                                      : method == visibility::HorizonMethod::exact
                                                          ? o.exact_variants
                                                          : std::vector<std::string>{"-"};
            for (const auto& variant : variants)
                for (int d : o.directions) {
                    visibility::HorizonOptions ho;
                    ho.method = method;
                    ho.directions = d;
                    ho.curvature = !o.no_curvature;
                    ho.threads = o.threads;
                    if (method == visibility::HorizonMethod::pyramid) ho.pyramid_schedule = variant;
                    if (method == visibility::HorizonMethod::exact) set_exact_variant(ho, variant);
                    t0.restart();
                    const visibility::HorizonSet set = visibility::compute_horizons(grid.view(), ho);
                    Row r;
                    r.time_ms = t0.milliseconds();
                    r.mean_tan_slope = roughness;
                    r.dem = name;
                    r.method = m;
                    r.variant = variant;
                    r.width = win.width;
                    r.height = win.height;
                    r.directions = d;
                    const bench::AbsoluteErrors hz = compare_horizons(ref, set);
                    r.horizon_rmse_deg = hz.rmse;
                    r.horizon_p99_deg = hz.p99;
                    const bench::AbsoluteErrors sv = compare(visibility::svf_raster(set, visibility::WedgeRule::linear, o.threads),
                                                  svf_ref, win.width, win.height);
                    r.svf_rmse = sv.rmse;
                    r.svf_p99 = sv.p99;
                    r.svf_rmse_constant =
                        compare(visibility::svf_raster(set, visibility::WedgeRule::constant, o.threads), svf_ref,
                                win.width, win.height)
                            .rmse;
                    const bench::AbsoluteErrors sk =
                        compare(visibility::sky_visible_raster(set, visibility::WedgeRule::linear, o.threads), sky_ref,
                                win.width, win.height);
                    r.sky_rmse = sk.rmse;
                    r.sky_p99 = sk.p99;
                    rows.push_back(r);
                    print_row(r);
                }
        }
        if (o.full) {
            // Speed on the whole DEM (no reference there): exact and pyramid.
            const visibility::VisibilityGrid whole(full);
            for (const auto& m : {std::string("exact"), std::string("pyramid")}) {
                visibility::HorizonOptions ho;
                ho.method = *visibility::parse_method(m);
                ho.directions = o.full_directions;
                ho.curvature = !o.no_curvature;
                ho.threads = o.threads;
                t0.restart();
                (void)visibility::compute_horizons(whole.view(), ho);
                Row r;
                r.time_ms = t0.milliseconds();
                r.dem = name;
                r.method = m;
                r.variant = "full-dem";
                r.width = full.width;
                r.height = full.height;
                r.directions = o.full_directions;
                rows.push_back(r);
                print_row(r);
            }
        }
        if (o.saga) run_saga(o, win, grid.view(), ref, rows, name);
        write_csv(o, rows);  // after every DEM, so a long run that fails later keeps its rows
    }
    if (!o.csv.empty()) std::printf("wrote %s\n", o.csv.c_str());
}

}  // namespace

void add_bench_visibility_command(CLI::App& bench) {
    auto o = std::make_shared<BenchVisibilityOptions>();
    CLI::App* cmd = bench.add_subcommand(
        "visibility",
        "Horizon methods against the raymarch reference on a centred window of each DEM: horizon error, "
        "svf and sky_visible RMSE / 99th percentile, time; --saga adds saga_cmd ta_lighting 3 side by side");
    cmd->add_option("DEM", o->dems, "DEM files, each measured on its own")->required();
    cmd->add_option("--window", o->window, "Centred window size in texels (the reference is brute force)")
        ->capture_default_str()
        ->check(within(8, 5000));
    cmd->add_option("--directions", o->directions, "Azimuth counts to measure")->delimiter(',')->capture_default_str();
    cmd->add_option("--methods", o->methods, "Methods to measure: exact, pyramid, raymarch")
        ->delimiter(',')
        ->capture_default_str();
    cmd->add_option("--pyramid-schedules", o->schedules, "pyramid schedules to measure: fast, balanced, fine, finest")
        ->delimiter(',')
        ->capture_default_str()
        ->check(CLI::IsMember({"fast", "balanced", "fine", "finest"}));
    cmd->add_option("--exact-variants", o->exact_variants,
                    "exact variants to measure, NEAR:LINES = near field in texels : sweep lines per texel")
        ->delimiter(',')
        ->capture_default_str();
    cmd->add_option("--reference-directions", o->reference_directions,
                    "Azimuths of the raymarch reference (svf integrated with linear wedges)")
        ->capture_default_str()
        ->check(within(8, 4096));
    cmd->add_flag("--full", o->full, "Also time exact and pyramid on the whole DEM");
    cmd->add_flag("--whole", o->whole,
                  "Instead of the window study: the whole DEM at --full-directions, GPU and CPU stage by stage "
                  "(median of --repeats), texel-azimuths per second, svf RMSE against the raymarch on the centred "
                  "--window, and saga_cmd ta_lighting 3 (defaults, same sectors) on a UTM copy made by gdalwarp");
    cmd->add_option("--whole-method", o->whole_method, "--whole: the horizon method timed (exact or pyramid)")
        ->capture_default_str()
        ->check(CLI::IsMember({"exact", "pyramid"}));
    cmd->add_option("--repeats", o->repeats, "--whole: runs per path (median reported)")
        ->capture_default_str()
        ->check(within(1, 20));
    cmd->add_flag("--no-saga", o->no_saga, "--whole: skip SAGA");
    cmd->add_flag("--exact-scalar", o->exact_scalar,
                  "--whole: sweep one line at a time even where the CPU has AVX-512 (A/B of the lane sweep)");
    cmd->add_option("--device", o->device, "--whole: Vulkan device index (terrashade devices)");
    cmd->add_option("--full-directions", o->full_directions, "Azimuths for --full and --whole")
        ->capture_default_str()
        ->check(within(1, 4096));
    cmd->add_flag("--no-curvature", o->no_curvature, "Flat Earth for every method (SAGA has no curvature)");
    cmd->add_flag("--saga", o->saga,
                  "Also run saga_cmd ta_lighting 3 (both its methods) on the window; projected DEMs only");
    cmd->add_option("--threads", o->threads, "Worker threads (0 = one per core)")->capture_default_str();
    cmd->add_option("--csv", o->csv, "Write the rows as CSV (input of scripts/chart_visibility.py)");
    cmd->callback([o] { run_bench_visibility(*o); });
}

}  // namespace ts::app
