// `terrashade visibility`: horizons per texel and azimuth on a real DEM, and what follows
// from them (sky view factor, visible sky, log-SH and SH visibility), as float32 GeoTIFFs
// georeferenced like the input.
#include <algorithm>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "app/quicklook_legend.hpp"
#include "app/command.hpp"
#include "app/compute_device.hpp"
#include "app/options/max_error_option.hpp"
#include "app/options/threads_option.hpp"
#include "app/job_memory.hpp"
#include "app/dem_input.hpp"
#include "app/io_plan.hpp"
#include "core/util/angles.hpp"
#include "core/raster/raster_writer.hpp"
#include "core/sh/exp_method.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/util/error.hpp"
#include "core/util/progress_bar.hpp"
#include "core/util/staged_outputs.hpp"
#include "core/quality/visibility_quality.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/horizon_sh.hpp"
#include "core/visibility/sky_integrals.hpp"
#include "core/visibility/visibility_backend.hpp"
#include "core/visibility/visibility_grid.hpp"
#include "core/util/stopwatch.hpp"
#include "core/raster/image_writer_registry.hpp"
#include "app/options/within_range.hpp"

namespace ts::app {
namespace {

struct VisibilityOptions {
    DemInput dem;
    visibility::HorizonOptions horizon;
    std::string method = "exact";
    std::string wedges = "linear";
    std::string exp_method = "hybrid";
    float log_eps = visibility::kDefaultVisibilityLogEps;
    bool no_curvature = false;
    double max_error = 0;  // --max-error: svf RMSE bound; 0 = the given settings
    bool directions_given = false, near_field_given = false;  // what --max-error would override
    std::string svf, sky_visible, horizons, sh, log_sh;
    DeviceArgs device;
};

bool is_png(const std::string& path) { return raster::written_as(path, raster::ImageWriter::png); }

// A fraction in [0, 1] (svf, sky_visible) as an 8-bit grey quick-look, to look at without a
// GIS: a linear stretch from the 1st to the 99th percentile of the valid values to grey 1..255
// (void 0). On real terrain most of the DEM is nearly open (the median svf of the Grenoble DEM is
// 0.99), so mapping 0..1 left the picture in the top half of the grey range with a fifth of it
// pure white; the stretch gives the relief the whole range, and the legend beside it
// (NAME_legend.png) and the printed line say which values the greys are. The GeoTIFF output
// keeps the values themselves.
struct Stretch {
    float lo = 0, hi = 1;
};

Stretch fraction_stretch(const dem::Dem& dem, const float* data) {
    const std::size_t n = std::size_t(dem.width) * dem.height;
    std::vector<float> valid;
    valid.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isnan(data[i])) valid.push_back(std::clamp(data[i], 0.0f, 1.0f));
    Stretch s;
    if (!valid.empty()) {
        auto at = [&](double q) {
            const auto k = std::size_t(q * double(valid.size() - 1));
            std::nth_element(valid.begin(), valid.begin() + std::ptrdiff_t(k), valid.end());
            return valid[k];
        };
        s.lo = at(0.01), s.hi = at(0.99);
        if (!(s.hi > s.lo)) s.lo = std::max(0.0f, s.hi - 1e-3f), s.hi = std::min(1.0f, s.lo + 1e-3f);  // a flat DEM
    }
    return s;
}

void write_fraction_png(const std::string& path, const dem::Dem& dem, const float* data, Stretch s) {
    const std::size_t n = std::size_t(dem.width) * dem.height;
    std::vector<std::uint8_t> grey(n);
    const float scale = 254.0f / (s.hi - s.lo);
    for (std::size_t i = 0; i < n; ++i) {
        const float v = data[i];
        grey[i] = std::isnan(v) ? 0 : std::uint8_t(1.5f + std::clamp((v - s.lo) * scale, 0.0f, 254.0f));
    }
    raster::write_u8_image(path, dem.width, dem.height, 1, grey.data(), nullptr);
}

// Stages one output (committed with the others at the end) and notes its "wrote" line; a PNG
// quick-look gets its legend beside it, titled `legend_title`.
void write_raster(StagedOutputs& outputs, std::vector<std::string>& wrote, const std::string& path,
                  const dem::Dem& dem, int bands, const float* data, const std::vector<std::string>& names,
                  const std::string& legend_title = {}) {
    if (is_png(path)) {
        const Stretch s = fraction_stretch(dem, data);
        const std::string legend = legend_path_for(path);
        outputs.stage(path, [&](const std::filesystem::path& tmp) { write_fraction_png(tmp.string(), dem, data, s); });
        outputs.stage(legend, [&](const std::filesystem::path& tmp) {
            write_legend_png(tmp.string(), dem.width, Legend{legend_title, "", s.lo, s.hi, grey_ramp});
        });
        std::printf("%s: grey 1..255 = %.4f..%.4f (the 1st to 99th percentile, stretched linearly; 0 = void), "
                    "legend in %s\n",
                    path.c_str(), s.lo, s.hi, legend.c_str());
        wrote.push_back("wrote " + path + " (grey quick-look) and " + legend + " (its legend)");
        return;
    }
    outputs.stage(path, [&](const std::filesystem::path& tmp) {
        raster::write_float_raster(tmp, dem.width, dem.height, bands, data, dem.georef, names);
    });
    wrote.push_back("wrote " + path + " (" + std::to_string(bands) + " band" + (bands == 1 ? "" : "s") + ")");
}

void run_visibility(VisibilityOptions& o) {
    if (o.svf.empty() && o.sky_visible.empty() && o.horizons.empty() && o.sh.empty() && o.log_sh.empty())
        throw InputError("visibility: nothing to write; give --svf, --sky-visible, --horizons, --sh or --log-sh");
    o.horizon.method = *visibility::parse_method(o.method);
    o.horizon.curvature = !o.no_curvature;
    if (o.max_error > 0 && o.horizon.method != visibility::HorizonMethod::exact)
        throw InputError("--max-error chooses the exact method's settings; drop --method " + o.method);
    if (o.max_error > 0 && (o.directions_given || o.near_field_given))
        throw InputError(std::string("--max-error chooses ") +
                         (o.directions_given ? "--directions" : "--exact-near-field") + " itself; drop one of them");
    const sh::ExpMethod exp_method = sh::parse_exp_method(o.exp_method);
    if ((!o.sh.empty() || !o.log_sh.empty()) && o.horizon.directions < 4)
        throw InputError("--sh/--log-sh: need at least 4 --directions");
    const auto rule = o.wedges == "constant" ? visibility::WedgeRule::constant : visibility::WedgeRule::linear;
    // Georeferenced float rasters, or an 8-bit quick-look of a fraction (write_fraction_png).
    const std::vector<std::string> extensions = raster::image_extensions([](const raster::ImageFormat& f) {
        return (f.float32 && f.georeferenced && f.multi_band) || f.writer == raster::ImageWriter::png;
    });
    IoPlan plan;
    plan.inputs("DEM", o.dem.files);
    plan.output("--svf", o.svf, extensions).output("--sky-visible", o.sky_visible, extensions);
    plan.output("--horizons", o.horizons, extensions).output("--sh", o.sh, extensions);
    plan.output("--log-sh", o.log_sh, extensions);
    for (const std::string* quick_look : {&o.svf, &o.sky_visible})
        if (is_png(*quick_look)) plan.output("the legend of " + *quick_look, legend_path_for(*quick_look), {".png"});
    plan.check();
    for (const std::string* multi_band : {&o.horizons, &o.sh, &o.log_sh})
        if (is_png(*multi_band))
            throw InputError(*multi_band + ": PNG holds only --svf or --sky-visible; use .tif for the " +
                             std::to_string(multi_band == &o.horizons ? o.horizon.directions : 16) + " bands");

    const dem::Dem dem = load_dem_input(o.dem);
    warn_if_single_line(dem);
    check_job_memory("visibility of " + std::to_string(dem.width) + "x" + std::to_string(dem.height) + " texels",
                     visibility_peak_bytes(std::uint64_t(dem.width) * dem.height, o.horizon.directions,
                                           !o.sh.empty() || !o.log_sh.empty()),
                     "use --crop, or fewer --directions (4 bytes per texel each)");
    const visibility::VisibilityGrid grid(dem);
    const std::size_t texels = std::size_t(dem.width) * dem.height;
    if (o.max_error > 0) {
        // Adaptive quality: the cheapest exact-sweep setting predicted under the bound for this
        // terrain's roughness (core/quality/visibility_quality.hpp); it replaces --directions
        // and --exact-near-field.
        const quality::VisibilityChoice choice =
            quality::choose_visibility(o.max_error, quality::mean_tan_slope(grid.view()));
        o.horizon.directions = choice.setting.directions;
        o.horizon.exact_near_field_texels = choice.setting.near_field_texels;
        std::fprintf(stderr, "terrashade: %s\n", max_error_line(choice.reason).c_str());
    }

    const ComputeDevice device(o.device);
    visibility::VisibilityRequest request;
    request.horizon = o.horizon;
    request.log_sh = !o.sh.empty() || !o.log_sh.empty();
    request.svf = !o.svf.empty();
    request.sky_visible = !o.sky_visible.empty();
    request.wedges = rule;
    request.log_eps = o.log_eps;
    ProgressBar bar("horizons (" + o.method + ")", texels * std::uint64_t(o.horizon.directions), "rays");
    request.horizon.progress = &bar;
    visibility::VisibilityResult result = device.visibility().compute(grid.view(), request);
    bar.finish();
    std::printf("%s horizons: %d directions, %dx%d texels (%s curvature)\n", o.method.c_str(), o.horizon.directions,
                dem.width, dem.height, o.no_curvature ? "no" : "with");
    for (const auto& stage : result.stages)
        std::printf("  %s on %s: %.3f s\n", stage.label.c_str(), stage.path.c_str(), stage.seconds);
    const visibility::HorizonSet& set = result.horizons;
    // Every output changes together at the end, or none does.
    StagedOutputs outputs;
    std::vector<std::string> wrote;

    if (!o.horizons.empty()) {
        // Bands in the user's order: azimuths clockwise from north, from the smallest (north
        // itself when D is a multiple of 4), whatever order the sweep uses inside.
        std::vector<int> order(std::size_t(set.directions));
        for (int d = 0; d < set.directions; ++d) order[std::size_t(d)] = d;
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
            return visibility::user_azimuth_deg(a, set.directions) < visibility::user_azimuth_deg(b, set.directions);
        });
        const std::size_t plane_texels = set.texels();
        std::vector<float> deg(set.angle.size());
        std::vector<std::string> names;
        for (std::size_t band = 0; band < order.size(); ++band) {
            const float* plane = set.plane(order[band]);
            for (std::size_t i = 0; i < plane_texels; ++i) deg[band * plane_texels + i] = float(degrees(plane[i]));
            char buf[96];
            std::snprintf(buf, sizeof buf, "horizon elevation (deg) toward azimuth %.4g deg clockwise from north",
                          visibility::user_azimuth_deg(order[band], set.directions));
            names.emplace_back(buf);
        }
        write_raster(outputs, wrote, o.horizons, dem, set.directions, deg.data(), names);
    }
    if (!o.svf.empty())
        write_raster(outputs, wrote, o.svf, dem, 1, result.svf.data(), {"svf: cosine-weighted visible sky, horizontal receiver"},
                     "sky view factor");
    if (!o.sky_visible.empty())
        write_raster(outputs, wrote, o.sky_visible, dem, 1, result.sky_visible.data(),
                     {"sky_visible: visible fraction of the upper hemisphere"}, "visible sky fraction");
    if (!o.sh.empty() || !o.log_sh.empty()) {
        const std::span<const float> log_sh(result.log_sh);
        std::vector<std::string> names;
        for (int i = 0; i < 16; ++i) {
            const int l = int(std::sqrt(double(i)));
            names.push_back("SH l=" + std::to_string(l) + " m=" + std::to_string(i - l * l - l));
        }
        if (!o.log_sh.empty()) write_raster(outputs, wrote, o.log_sh, dem, 16, log_sh.data(), names);
        if (!o.sh.empty()) {
            const Stopwatch t1;
            const auto vis = visibility::exp_sh_raster(log_sh, texels, exp_method, o.horizon.threads);
            std::printf("exp (%s): %.3f s\n", o.exp_method.c_str(), t1.seconds());
            write_raster(outputs, wrote, o.sh, dem, 16, vis.data(), names);
        }
    }
    outputs.commit();
    for (const std::string& line : wrote) std::printf("%s\n", line.c_str());
}

}  // namespace

void add_visibility_command(CLI::App& root) {
    auto o = std::make_shared<VisibilityOptions>();
    CLI::App* cmd = root.add_subcommand(
        "visibility",
        "Horizons per texel and azimuth, sky view factor, visible sky and (log-)SH visibility "
        "(docs/visibility.md). Void (nodata) texels neither block nor receive: their outputs are NaN.");
    add_dem_input_options(*cmd, o->dem, false);
    cmd->add_option("--directions", o->horizon.directions,
                    "Azimuths D, evenly spaced (--horizons bands: clockwise from north, from the smallest azimuth)")
        ->capture_default_str()
        ->check(within(1, 4096))
        ->each([o](const std::string&) { o->directions_given = true; });
    cmd->add_option("--method", o->method,
                    "exact: convex-hull sweep (fast, exact up to sweep-line interpolation); pyramid: the slides' "
                    "multi-resolution marching (approximate); raymarch: brute force reference (slow)")
        ->capture_default_str()
        ->check(CLI::IsMember({"exact", "pyramid", "raymarch"}));
    cmd->add_option("--pyramid-schedule", o->horizon.pyramid_schedule,
                    "pyramid: samples per octave of distance, fast=2, balanced=4, fine=8, finest=16")
        ->capture_default_str()
        ->check(CLI::IsMember({"fast", "balanced", "fine", "finest"}));
    cmd->add_option("--exact-lines-per-texel", o->horizon.exact_lines_per_texel,
                    "exact: sweep lines per texel across each azimuth (2 halves the interpolation distance, 2x time)")
        ->capture_default_str()
        ->check(within(1, 4));
    cmd->add_option("--max-error", o->max_error,
                    "Adaptive quality: the cheapest --directions and --exact-near-field whose predicted svf RMSE "
                    "stays under this for the DEM's roughness (e.g. 0.001); prints what it chose and why (so not "
                    "with either of them)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--exact-near-field", o->horizon.exact_near_field_texels,
                    "exact: march each receiver's first N texels from the texel centre itself (0 = pure sweep)")
        ->capture_default_str()
        ->check(within(0.0, 64.0))
        ->each([o](const std::string&) { o->near_field_given = true; });
    cmd->add_flag_callback(
        "--exact-scalar", [o] { o->horizon.exact_simd_lines = false; },
        "exact: sweep one line at a time even where the CPU has AVX-512 (bit-identical, slower; for comparisons)");
    cmd->add_flag("--no-curvature", o->no_curvature,
                  "Ignore Earth curvature (default: drop d^2/(2 R_eff), R_eff = R/(1-0.13) with refraction)");
    cmd->add_option("--wedges", o->wedges,
                    "svf/sky-visible integration across azimuth: linear (horizon interpolated between azimuths) "
                    "or constant (each horizon holds over its sector, as GIS tools do)")
        ->capture_default_str()
        ->check(CLI::IsMember({"linear", "constant"}));
    cmd->add_option("--svf", o->svf, "Write the sky view factor (1/pi) int V cos(theta) dw: float32 GeoTIFF (.tif) or 8-bit grey quick-look (.png)");
    cmd->add_option("--sky-visible", o->sky_visible,
                    "Write the visible sky fraction (1/2pi) int V dw: float32 GeoTIFF (.tif) or 8-bit grey quick-look (.png)");
    cmd->add_option("--horizons", o->horizons,
                    "Write the horizon elevation angles, D bands in degrees, band 1 toward north (D a multiple of "
                    "4), then clockwise; each band's description names its azimuth");
    cmd->add_option("--sh", o->sh, "Write the visibility SH (16 bands), exp of the log-SH with --exp-method");
    cmd->add_option("--log-sh", o->log_sh, "Write the log-SH visibility (16 bands)");
    cmd->add_option("--exp-method", o->exp_method, "SH exponentiation (" + sh::exp_method_choices() + ")")
        ->capture_default_str();
    cmd->add_option("--log-eps", o->log_eps, "log of the visibility floor below the horizon")
        ->capture_default_str()
        ->check(within(-50.0, -1e-3));
    add_threads_option(*cmd, o->horizon.threads);
    add_device_options(*cmd, o->device);
    cmd->callback([o] { run_visibility(*o); });
}

}  // namespace ts::app
