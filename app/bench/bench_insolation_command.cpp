// `terrashade bench insolation`: terrashade insolation against GRASS r.sun (with and without
// r.horizon maps) and SAGA's Potential Incoming Solar Radiation on one centred crop of a DEM, in
// one run: wall and CPU time per tool, and r.sun's beam against terrashade's beam, texel by
// texel, on open terrain and elsewhere (docs/insolation.md). Its CSV and --maps feed
// scripts/chart_insolation.py.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "app/bench/bench_command.hpp"
#include "app/bench/csv_number.hpp"
#include "app/bench/error_stats.hpp"
#include "app/bench/grass_session.hpp"
#include "app/bench/insolation_agreement.hpp"
#include "app/bench/shell_command.hpp"
#include "app/bench/timed_shell.hpp"
#include "app/io_plan.hpp"
#include "app/options/within_range.hpp"
#include "core/dem/read_dem.hpp"
#include "core/raster/raster_writer.hpp"
#include "core/solar/insolation_period.hpp"
#include "core/util/error.hpp"
#include "core/util/staged_outputs.hpp"
#include "core/util/temp_files.hpp"

namespace ts::app {
// Its own namespace: a unity batch compiles it with other benches' anonymous Row, kNaN, ...
namespace insolation_bench {
namespace {

namespace fs = std::filesystem;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct BenchInsolationOptions {
    std::string dem;
    int window = 360;
    std::string date = "2024-06-21";
    double linke = 3.0, albedo = 0.2;
    double step_hours = 0.5;  // r.sun's and SAGA's time step (terrashade keeps its 2 min)
    int horizons = 32;        // r.horizon maps given to r.sun
    int threads = 2;
    int repeats = 3;  // timed runs of each tool; the median is reported
    double open_horizon_deg = 5, open_slope_deg = 5;
    bool no_grass = false, no_saga = false;
    int saga_timeout_s = 300;
    std::string csv, maps;
};

struct SpeedRow {
    std::string tool, what, period;
    TimedRun run;
    bool compared = true;  // a whole tool's time for the period (a preparatory step alone is not)
    // Wall and CPU time / terrashade's for the same period (set_ratios). CPU too: a shared
    // machine inflates wall times, CPU times much less.
    double ratio = kNaN, cpu_ratio = kNaN;
};

void set_ratios(std::vector<SpeedRow>& rows) {
    for (SpeedRow& r : rows) {
        if (!r.compared || !r.run.ok) continue;
        for (const SpeedRow& t : rows)
            if (t.tool == "terrashade" && t.period == r.period && t.run.ok) {
                r.ratio = r.run.wall_s / t.run.wall_s;
                r.cpu_ratio = r.run.cpu_s / t.run.cpu_s;
            }
    }
}

// The DEM's centred window of n x n texels (n clamped to the DEM), voids as NaN.
dem::Dem centre_crop(const dem::Dem& d, int n) {
    const int w = std::min(n, d.width), h = std::min(n, d.height);
    const int c0 = (d.width - w) / 2, r0 = (d.height - h) / 2;
    dem::Dem out;
    out.width = w;
    out.height = h;
    out.z.resize(std::size_t(w) * h);
    out.void_mask.assign(out.z.size(), 0);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            const bool hole = !d.void_mask.empty() && d.is_void(c0 + c, r0 + r);
            out.z[std::size_t(r) * w + c] = hole ? std::numeric_limits<float>::quiet_NaN() : d.at(c0 + c, r0 + r);
        }
    out.georef = d.georef.window(c0, r0, w, h);
    out.source = d.source;
    return out;
}

// One band of a GeoTIFF as floats, its voids (nodata) as NaN, `scale` applied.
std::vector<float> read_band(const fs::path& file, int band, const fs::path& dir, double scale, std::size_t texels) {
    const fs::path one = dir / ("band_" + file.stem().string() + "_" + std::to_string(band) + ".tif");
    if (std::system(("gdal_translate -q -b " + std::to_string(band) + " " + shell_quote(file.string()) + " " +
                     shell_quote(one.string()) + " > /dev/null 2>&1")
                        .c_str()) != 0)
        throw InputError("gdal_translate could not read band " + std::to_string(band) + " of " + file.string());
    const dem::Dem d = dem::read_dem(one);
    if (d.z.size() != texels) throw InputError(file.string() + ": not the crop's size");
    std::vector<float> v(d.z);
    for (std::size_t i = 0; i < v.size(); ++i)
        v[i] = (!d.void_mask.empty() && d.void_mask[i]) ? std::numeric_limits<float>::quiet_NaN() : float(v[i] * scale);
    return v;
}

int day_of_year(const solar::CalendarDate& d) {
    using namespace std::chrono;
    const sys_days day = year(d.year) / month(unsigned(d.month)) / std::chrono::day(unsigned(d.day));
    const sys_days first = year(d.year) / January / 1;
    return int((day - first).count()) + 1;
}

std::string number(double v) {
    std::ostringstream s;
    s.precision(10);
    s << v;
    return s.str();
}

// The GRASS steps: import, slope and aspect, the horizon maps, r.sun without them (its own
// shadowing, ray-traced per step) and with them, and the maps the comparison reads.
std::string grass_script(const BenchInsolationOptions& o, const fs::path& crop, const fs::path& dir, int day) {
    const double hstep = 360.0 / o.horizons;
    // --overwrite: the modules run --repeats times.
    const std::string common = " elevation=dem slope=slope aspect=aspect linke_value=" + number(o.linke) +
                               " albedo_value=" + number(o.albedo) + " day=" + std::to_string(day) +
                               " step=" + number(o.step_hours) + " nprocs=" + std::to_string(o.threads) +
                               " --quiet --overwrite";
    // Every r.sun run writes all five outputs, so their times compare.
    auto outputs = [](const std::string& tag) {
        return " beam_rad=beam_" + tag + " diff_rad=diff_" + tag + " refl_rad=refl_" + tag + " glob_rad=glob_" + tag +
               " insol_time=time_" + tag + "\n";
    };
    std::ostringstream s;
    s << "r.in.gdal -o input=" << shell_quote(crop.string()) << " output=dem --quiet\n"
      << "g.region raster=dem\n"
      << "for rep in $(seq " << o.repeats << "); do\n"
      << "timed slope_aspect r.slope.aspect elevation=dem slope=slope aspect=aspect --quiet --overwrite\n"
      << "timed horizon r.horizon elevation=dem step=" << number(hstep) << " output=hor --quiet --overwrite\n"
      << "timed sun_own r.sun" << common << outputs("own")
      << "timed sun_horizons r.sun" << common << " horizon_basename=hor horizon_step=" << number(hstep) << outputs("hz")
      // r.horizon writes negative angles where the ground falls away all round (peaks, the
      // crop's edges); r.sun 8.2 then shades such a texel most of the day (docs/insolation.md). The
      // same maps raised to 0 show what r.sun computes once that is worked around.
      << "for h in $(g.list raster pattern='hor_*'); do\n"
      << "  r.mapcalc \"zero_$h = max($h, 0.0)\" --quiet --overwrite\n"
      << "done\n"
      << "timed sun_clamped r.sun" << common << " horizon_basename=zero_hor horizon_step=" << number(hstep)
      << outputs("zero")
      << "done\n"
      << "r.series input=$(g.list raster pattern='hor_*' separator=comma) output=horizon_max method=maximum --quiet\n"
      << "for m in beam_own time_own beam_hz time_hz beam_zero time_zero slope horizon_max; do\n"
      << "  r.out.gdal -c input=$m output=" << shell_quote(dir.string()) << "/grass_$m.tif type=Float32 --quiet\n"
      << "done\n";
    return s.str();
}

// A text cell as RFC 4180 writes it: quoted (quotes doubled) when it holds a comma or a quote.
std::string csv_cell(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

std::string csv_text(const BenchInsolationOptions& o, const std::string& dem_name, int w, int h,
                     const std::vector<SpeedRow>& speed, const std::vector<AgreementRow>& agree) {
    std::ostringstream csv;
    csv << "section,dem,width,height,date,tool,what,period,wall_s,cpu_s,wall_ratio,cpu_ratio,rsun,texels,n,"
           "mean_rel,p5_rel,p50_rel,p95_rel,within_2pct,hours_diff\n";
    const std::string head = csv_cell(dem_name) + ',' + std::to_string(w) + ',' + std::to_string(h) + ',' + o.date + ',';
    for (const SpeedRow& r : speed)
        csv << "speed," << head << csv_cell(r.tool) << ',' << csv_cell(r.what) << ',' << r.period << ','
            << csv_number(r.run.ok ? r.run.wall_s : kNaN) << ',' << csv_number(r.run.ok ? r.run.cpu_s : kNaN) << ','
            << csv_number(r.ratio) << ',' << csv_number(r.cpu_ratio) << ",,,,,,,,,\n";
    for (const AgreementRow& a : agree)
        csv << "beam," << head << ",,,,,,," << csv_cell(a.rsun) << ',' << a.texels << ',' << a.n << ',' << csv_number(a.mean)
            << ',' << csv_number(a.p5) << ',' << csv_number(a.p50) << ',' << csv_number(a.p95) << ','
            << csv_number(a.within_2pct) << ',' << csv_number(a.hours_diff) << '\n';
    return csv.str();
}

void print_speed(const std::vector<SpeedRow>& rows) {
    std::printf("\n%-16s %-44s %-7s %9s %9s %9s %9s\n", "tool", "what", "period", "wall_s", "cpu_s", "wall/ts",
                "cpu/ts");
    for (const SpeedRow& r : rows) {
        if (!r.run.ok) {
            std::printf("%-16s %-44s %-7s %9s\n", r.tool.c_str(), r.what.c_str(), r.period.c_str(), "failed");
            continue;
        }
        std::printf("%-16s %-44s %-7s %9.2f %9.2f %9.2f %9.2f\n", r.tool.c_str(), r.what.c_str(), r.period.c_str(),
                    r.run.wall_s, r.run.cpu_s, r.ratio, r.cpu_ratio);
    }
}

void print_agreement(const std::vector<AgreementRow>& rows) {
    std::printf("\nbeam, r.sun / terrashade - 1 (hours: r.sun insol_time - terrashade hours of direct sun)\n");
    std::printf("%-22s %-10s %7s %8s %8s %8s %8s %9s %8s\n", "r.sun", "texels", "n", "mean", "p5", "median", "p95",
                "|d|<=2%", "hours");
    for (const AgreementRow& a : rows)
        std::printf("%-22s %-10s %7zu %7.2f%% %7.2f%% %7.2f%% %7.2f%% %8.1f%% %8.2f\n", a.rsun.c_str(),
                    a.texels.c_str(), a.n, 100 * a.mean, 100 * a.p5, 100 * a.p50, 100 * a.p95, 100 * a.within_2pct,
                    a.hours_diff);
}

std::string terrashade_binary() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) throw InputError("bench insolation: cannot find its own executable (/proc/self/exe)");
    const fs::path bin = self.parent_path() / "terrashade";
    if (!fs::exists(bin)) throw InputError("bench insolation: no terrashade beside " + self.string());
    return bin.string();
}

// SAGA's Potential Incoming Solar Radiation (ta_lighting 2, Hofierka and Suri's atmosphere, the
// same Linke turbidity) for the day on a UTM copy of the crop: SAGA takes cell sizes in map units.
SpeedRow run_saga(const BenchInsolationOptions& o, const fs::path& crop, const fs::path& dir, double lon, double lat) {
    SpeedRow row{"saga", "ta_lighting 2, UTM copy, step " + number(o.step_hours) + " h", "day", {}};
    const int zone = std::clamp(int(std::floor((lon + 180) / 6)) + 1, 1, 60);
    const std::string epsg = "EPSG:" + std::to_string((lat >= 0 ? 32600 : 32700) + zone);
    const fs::path utm = dir / "saga_utm.tif", log = dir / "saga.log";
    if (std::system(("gdalwarp -q -overwrite -t_srs " + epsg + " -tr 92 92 -r bilinear " + shell_quote(crop.string()) +
                     " " + shell_quote(utm.string()) + " > " + shell_quote(log.string()) + " 2>&1")
                        .c_str()) != 0)
        throw InputError("gdalwarp failed; see " + log.string());
    const std::string cmd = "timeout " + std::to_string(o.saga_timeout_s) + " saga_cmd ta_lighting 2 -GRD_DEM " +
                            shell_quote(utm.string()) + " -GRD_DIRECT " + shell_quote((dir / "saga_direct.tif").string()) +
                            " -GRD_DIFFUS " + shell_quote((dir / "saga_diffuse.tif").string()) +
                            " -GRD_LINKE_DEFAULT " + number(o.linke) + " -METHOD 3 -LOCATION 1 -PERIOD 1 -DAY " +
                            o.date + " -HOUR_RANGE_MIN 0 -HOUR_RANGE_MAX 24 -HOUR_STEP " + number(o.step_hours) +
                            " > " + shell_quote(log.string()) + " 2>&1";
    row.run = run_timed(cmd, o.repeats);
    if (!row.run.ok) {
        // The log goes with the bench's temporary folder: its last line says why.
        std::ifstream in(log);
        std::string line, last;
        while (std::getline(in, line))
            if (!line.empty()) last = line;
        std::printf("saga: failed or gave up after %d s (--saga-timeout); its last words: %s\n", o.saga_timeout_s,
                    last.c_str());
    }
    return row;
}

void run_bench_insolation(const BenchInsolationOptions& o) {
    IoPlan plan;
    plan.input("DEM", o.dem).output("--csv", o.csv, {".csv"}).output("--maps", o.maps, {".tif"});
    plan.check();
    const solar::CalendarDate date = solar::parse_calendar_date(o.date, "--date");
    const int day = day_of_year(date);
    if (day > 365 && !o.no_grass) throw InputError("--date: r.sun takes days 1..365; 31 December of a leap year has none");
    if (!o.maps.empty() && (o.no_grass || !on_path("grass")))
        throw InputError("--maps: the beam maps need r.sun (GRASS: scripts/setup.sh bench; not with --no-grass)");
    const std::string bin = terrashade_binary();
    for (const char* tool : {"gdal_translate", "gdalwarp"})
        if (!on_path(tool)) throw InputError(std::string("bench insolation needs ") + tool + " (Debian gdal-bin)");

    const dem::Dem full = dem::read_dem(o.dem);
    if (!full.georef.crs().is_geographic())
        throw input_error(o.dem, "bench insolation needs a longitude/latitude DEM (r.sun runs in an EPSG:4326 location)");
    const dem::Dem crop = centre_crop(full, o.window);
    const std::size_t texels = crop.z.size();
    const std::string dem_name = fs::path(o.dem).filename().string();
    const glm::dvec2 centre = crop.georef.pixel_to_lonlat(crop.width * 0.5, crop.height * 0.5);

    const fs::path dir = fs::temp_directory_path() / ("terrashade-bench-insolation-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    temp_files::track_directory(dir);  // an interrupt removes it, the GRASS location inside included
    const fs::path crop_tif = dir / "crop.tif";
    raster::write_float_raster(crop_tif, crop.width, crop.height, 1, crop.z.data(), crop.georef);
    std::printf("bench insolation: %s, centred %dx%d crop (centre %.4f, %.4f), %s (day %d), Linke %g, albedo %g\n",
                dem_name.c_str(), crop.width, crop.height, centre.x, centre.y, o.date.c_str(), day, o.linke, o.albedo);
    std::fflush(stdout);

    // terrashade: the day, then the year (2-minute step, 64 horizon azimuths: its defaults).
    std::vector<SpeedRow> speed;
    const std::string ts_common = " --linke " + number(o.linke) + " --albedo " + number(o.albedo) + " --threads " +
                                  std::to_string(o.threads) + " > " + shell_quote((dir / "terrashade.log").string()) +
                                  " 2>&1";
    const fs::path ts_day = dir / "ts_day.tif", ts_year = dir / "ts_year.tif";
    SpeedRow day_row{"terrashade", "insolation, 64 horizon azimuths, step 2 min", "day", {}};
    day_row.run = run_timed(shell_quote(bin) + " insolation " + shell_quote(crop_tif.string()) + " --from " + o.date +
                            " --to " + o.date + " --out " + shell_quote(ts_day.string()) + ts_common,
                            o.repeats);
    if (!day_row.run.ok) throw InputError("terrashade insolation failed; see " + (dir / "terrashade.log").string());
    SpeedRow year_row{"terrashade", "insolation, 64 horizon azimuths, step 2 min", "year", {}};
    year_row.run = run_timed(shell_quote(bin) + " insolation " + shell_quote(crop_tif.string()) + " --year " +
                             std::to_string(date.year) + " --out " + shell_quote(ts_year.string()) + ts_common,
                             o.repeats);
    if (!year_row.run.ok) throw InputError("terrashade insolation --year failed; see " + (dir / "terrashade.log").string());
    speed.push_back(day_row);
    speed.push_back(year_row);

    std::vector<AgreementRow> agree;
    std::vector<float> beam_ts = read_band(ts_day, 2, dir, 1000.0, texels);  // kWh/m2 -> Wh/m2, as r.sun
    std::vector<float> hours_ts = read_band(ts_day, 5, dir, 1.0, texels);
    std::vector<float> beam_hz, beam_zero, beam_own, open_mask;
    if (o.no_grass) {
        std::printf("r.sun: skipped (--no-grass)\n");
    } else if (!on_path("grass")) {
        std::printf("r.sun: skipped (grass not installed: Debian grass-core, scripts/setup.sh bench)\n");
    } else {
        std::map<std::string, TimedRun> t;
        {
            GrassSession grass(dir, "EPSG:4326");
            t = grass.run(grass_script(o, crop_tif, dir, day));
        }  // the location is removed here
        const std::string step = "step " + number(o.step_hours) + " h";
        const std::string nh = std::to_string(o.horizons);
        auto add = [&](const std::string& tool, const std::string& what, const TimedRun& run, bool compared) {
            speed.push_back(SpeedRow{tool, what, "day", run, compared});
        };
        add("r.slope.aspect", "slope and aspect for r.sun", t["slope_aspect"], false);
        add("r.horizon", nh + " horizon maps", t["horizon"], false);
        add("r.sun", "own shadowing (no horizon maps), " + step, t["sun_own"], true);
        add("r.sun", nh + " r.horizon maps, " + step, t["sun_horizons"], true);
        add("r.sun", nh + " maps raised to 0 deg, " + step, t["sun_clamped"], true);
        const TimedRun both{true, t["horizon"].wall_s + t["sun_horizons"].wall_s,
                            t["horizon"].cpu_s + t["sun_horizons"].cpu_s};
        add("r.horizon+r.sun", nh + " maps then r.sun, " + step, both, true);
        // Not measured: what 365 days of r.sun would take at the day's cost (the maps made once).
        const TimedRun year_est{true, t["horizon"].wall_s + 365 * t["sun_horizons"].wall_s,
                                t["horizon"].cpu_s + 365 * t["sun_horizons"].cpu_s};
        speed.push_back(SpeedRow{"r.sun (est.)", "r.horizon once + 365 x the day above", "year", year_est});

        beam_hz = read_band(dir / "grass_beam_hz.tif", 1, dir, 1.0, texels);
        beam_own = read_band(dir / "grass_beam_own.tif", 1, dir, 1.0, texels);
        const std::vector<float> hours_hz = read_band(dir / "grass_time_hz.tif", 1, dir, 1.0, texels);
        const std::vector<float> hours_own = read_band(dir / "grass_time_own.tif", 1, dir, 1.0, texels);
        beam_zero = read_band(dir / "grass_beam_zero.tif", 1, dir, 1.0, texels);
        const std::vector<float> hours_zero = read_band(dir / "grass_time_zero.tif", 1, dir, 1.0, texels);
        const std::vector<float> slope = read_band(dir / "grass_slope.tif", 1, dir, 1.0, texels);
        const std::vector<float> hmax = read_band(dir / "grass_horizon_max.tif", 1, dir, 180.0 / M_PI, texels);
        // Open terrain: gentle slope and a low horizon all round (the r.horizon maps r.sun is given),
        // where neither model's terrain handling matters and the sky models alone are compared.
        std::vector<std::uint8_t> open(texels, 0), rest(texels, 0);
        open_mask.assign(texels, std::numeric_limits<float>::quiet_NaN());
        for (std::size_t i = 0; i < texels; ++i) {
            if (!std::isfinite(slope[i]) || !std::isfinite(hmax[i])) continue;
            open[i] = slope[i] < o.open_slope_deg && hmax[i] < o.open_horizon_deg;
            rest[i] = !open[i];
            open_mask[i] = open[i];
        }
        agree.push_back(agreement("r.horizon maps", "open", beam_hz, beam_ts, hours_hz, hours_ts, open));
        agree.push_back(agreement("r.horizon maps", "elsewhere", beam_hz, beam_ts, hours_hz, hours_ts, rest));
        agree.push_back(agreement("maps raised to 0", "open", beam_zero, beam_ts, hours_zero, hours_ts, open));
        agree.push_back(agreement("maps raised to 0", "elsewhere", beam_zero, beam_ts, hours_zero, hours_ts, rest));
        agree.push_back(agreement("own shadowing", "open", beam_own, beam_ts, hours_own, hours_ts, open));
        agree.push_back(agreement("own shadowing", "elsewhere", beam_own, beam_ts, hours_own, hours_ts, rest));
    }
    if (o.no_saga) {
        std::printf("saga: skipped (--no-saga)\n");
    } else if (!on_path("saga_cmd")) {
        std::printf("saga: skipped (saga_cmd not installed: Debian saga)\n");
    } else {
        speed.push_back(run_saga(o, crop_tif, dir, centre.x, centre.y));
    }
    set_ratios(speed);
    print_speed(speed);
    if (!agree.empty()) print_agreement(agree);

    StagedOutputs outputs;
    if (!o.csv.empty())
        outputs.stage(o.csv, [&](const fs::path& tmp) {
            std::ofstream out(tmp, std::ios::binary);
            out << csv_text(o, dem_name, crop.width, crop.height, speed, agree);
            if (!out.flush()) throw input_error(o.csv, "cannot write");
        });
    if (!o.maps.empty()) {
        // Band order: terrashade beam, r.sun beam with the maps, with the maps raised to 0, with
        // its own shadowing (Wh/m2 over the day), open terrain (1) or not (0).
        std::vector<float> bands;
        for (const auto* b : {&beam_ts, &beam_hz, &beam_zero, &beam_own, &open_mask})
            bands.insert(bands.end(), b->begin(), b->end());
        outputs.stage(o.maps, [&](const fs::path& tmp) {
            raster::write_float_raster(tmp, crop.width, crop.height, 5, bands.data(), crop.georef,
                                       {"terrashade beam (Wh/m2)", "r.sun beam, r.horizon maps (Wh/m2)",
                                        "r.sun beam, r.horizon maps raised to 0 (Wh/m2)",
                                        "r.sun beam, own shadowing (Wh/m2)", "open terrain (1) or not (0)"});
        });
    }
    outputs.commit();
    for (const std::string* p : {&o.csv, &o.maps})
        if (!p->empty()) std::printf("wrote %s\n", p->c_str());
    fs::remove_all(dir);
    temp_files::forget_directory(dir);
}

}  // namespace
}  // namespace insolation_bench

void add_bench_insolation_command(CLI::App& bench) {
    using namespace insolation_bench;
    auto o = std::make_shared<BenchInsolationOptions>();
    CLI::App* cmd = bench.add_subcommand(
        "insolation",
        "terrashade insolation (a day and the year) against GRASS r.sun (own shadowing, and r.horizon maps) and "
        "saga_cmd ta_lighting 2 on a centred crop: wall and CPU seconds, and r.sun's beam vs terrashade's per texel");
    cmd->add_option("DEM", o->dem, "A longitude/latitude DEM (e.g. an SRTM .hgt)")->required();
    cmd->add_option("--window", o->window, "Centred crop size in texels")->capture_default_str()->check(within(8, 4000));
    cmd->add_option("--date", o->date, "The day compared, YYYY-MM-DD (its year is the year timed)")->capture_default_str();
    cmd->add_option("--linke", o->linke, "Linke turbidity for every tool")->capture_default_str()->check(within(0.5, 10.0));
    cmd->add_option("--albedo", o->albedo, "Ground albedo for every tool")->capture_default_str()->check(within(0.0, 1.0));
    cmd->add_option("--step", o->step_hours, "r.sun's and SAGA's time step, hours")
        ->capture_default_str()
        ->check(within(0.01, 2.0));
    cmd->add_option("--horizons", o->horizons, "r.horizon maps given to r.sun (360 / step)")
        ->capture_default_str()
        ->check(within(4, 360));
    cmd->add_option("--threads", o->threads, "Threads for terrashade and r.sun (nprocs)")
        ->capture_default_str()
        ->check(within(1, 256));
    cmd->add_option("--open-horizon", o->open_horizon_deg, "Open terrain: highest r.horizon angle below this, degrees")
        ->capture_default_str()
        ->check(within(0.0, 90.0));
    cmd->add_option("--open-slope", o->open_slope_deg, "Open terrain: slope below this, degrees")
        ->capture_default_str()
        ->check(within(0.0, 90.0));
    cmd->add_option("--repeats", o->repeats, "Timed runs of each tool (the median is reported)")
        ->capture_default_str()
        ->check(within(1, 20));
    cmd->add_flag("--no-grass", o->no_grass, "Skip r.sun and r.horizon");
    cmd->add_flag("--no-saga", o->no_saga, "Skip SAGA");
    cmd->add_option("--saga-timeout", o->saga_timeout_s, "Give SAGA up after this many seconds")
        ->capture_default_str()
        ->check(within(1, 86400));
    cmd->add_option("--csv", o->csv, "Write the speed and beam rows as CSV (input of scripts/chart_insolation.py)");
    cmd->add_option("--maps", o->maps,
                    "Write the beam maps (terrashade, r.sun with the maps, with them raised to 0, with its own "
                    "shadowing; Wh/m2) and the open mask as a 5-band float GeoTIFF (input of scripts/chart_insolation.py)");
    cmd->callback([o] { run_bench_insolation(*o); });
}

}  // namespace ts::app
