// `terrashade bench report`: one CSV over the speed/accuracy knobs of every command. It runs
// the other bench commands (this same executable, one child process per study, so each study's
// code and reference stay where they are) on crops of the shared DEMs and turns their CSVs into
// rows of (command, knob, value, is_default, seconds, error, error_metric, dem). The charts come
// from scripts/chart_report.py; docs/accuracy.md reads them.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "app/bench/bench_command.hpp"
#include "app/bench/report_table.hpp"
#include "app/bench/shell_command.hpp"
#include "app/io_plan.hpp"
#include "core/util/error.hpp"
#include "core/util/progress_bar.hpp"
#include "core/util/staged_outputs.hpp"
#include "core/util/stopwatch.hpp"
#include "core/util/temp_files.hpp"

namespace ts::app {
namespace {

using bench::CsvRecord;
using bench::ReportRow;
using bench::csv_field;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

enum class Size { tiny, quick, full };

struct BenchReportOptions {
    bool quick = false;
    bool tiny = false;  // hidden: the smallest matrix, for the CLI test of the CSV's shape
    std::string out = "docs/charts";
    std::string data = "../shared/data";
    std::vector<std::string> only;  // studies to run (default all)
    std::string reference_dir = "tests/render/reference";  // the stored Cycles pictures
};

// One study: a bench command line, its expected duration, and how its output becomes rows.
struct Study {
    std::string name;
    std::string args;  // after `terrashade bench`, without --csv
    std::vector<std::string> inputs;  // files it reads beyond the shared data (checked before any study runs)
    double expected_s = 0;
    bool writes_csv = true;
    std::function<void(const std::vector<CsvRecord>& csv, const std::string& log, std::vector<ReportRow>& rows)> parse;
};

std::string read_text(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string dem_name(const std::string& path) {
    return std::filesystem::path(path).filename().string();
}

std::string format_value(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// bench visibility on a centred window: every horizon knob in one run (one reference).
Study visibility_study(const std::string& dem, Size size) {
    const int window = size == Size::tiny ? 24 : size == Size::quick ? 100 : 240;
    const int ref = size == Size::full ? 256 : 128;
    Study s;
    s.name = "visibility knobs on " + dem_name(dem);
    s.expected_s = size == Size::tiny ? 2 : size == Size::quick ? 25 : 240;
    const std::string dirs = size == Size::tiny ? "8,16,32" : "8,16,32,64";
    s.args = "visibility " + shell_quote(dem) + " --window " + std::to_string(window) + " --reference-directions " +
             std::to_string(ref) + " --methods exact,pyramid,raymarch --directions " + dirs +
             (size == Size::tiny ? " --exact-variants 0:1,2:1,8:1 --pyramid-schedules fast,balanced"
                                 : " --exact-variants 0:1,1:1,2:1,4:1,8:1,2:2,2:3 --pyramid-schedules "
                                   "fast,balanced,fine,finest");
    s.parse = [dem](const std::vector<CsvRecord>& csv, const std::string&, std::vector<ReportRow>& rows) {
        for (const CsvRecord& r : csv) {
            const std::string m = r.at("method"), v = r.at("variant");
            const int d = int(csv_field(r, "directions"));
            ReportRow row;
            row.command = "visibility";
            row.seconds = csv_field(r, "time_ms") / 1000.0;
            row.error = csv_field(r, "svf_rmse");
            row.error_metric = "svf_rmse";
            row.dem = dem_name(dem);
            auto add = [&](const std::string& knob, const std::string& value, bool is_default) {
                row.knob = knob;
                row.value = value;
                row.is_default = is_default;
                rows.push_back(row);
            };
            if (m == "exact" && v == "2:1") add("directions", std::to_string(d), d == 32);
            if (d == 32 && ((m == "exact" && v == "2:1") || (m == "pyramid" && v == "balanced") || m == "raymarch"))
                add("horizon_method", m, m == "exact");
            if (d == 32 && m == "pyramid") add("pyramid_schedule", v, v == "balanced");
            if (d == 32 && m == "exact" && v.size() > 2 && v.substr(v.size() - 2) == ":1")
                add("exact_near_field", v.substr(0, v.size() - 2), v == "2:1");
            if (d == 32 && m == "exact" && v.rfind("2:", 0) == 0) add("exact_lines", v.substr(2), v == "2:1");
        }
    };
    return s;
}

// bench render at several D: the renderer's radiance against the ray-traced reference.
Study render_study(const std::string& dem, int directions, Size size) {
    Study s;
    s.name = "render --directions " + std::to_string(directions) + " on " + dem_name(dem);
    const int samples = size == Size::tiny ? 20 : size == Size::quick ? 120 : 600;
    s.expected_s = size == Size::tiny ? 6 : size == Size::quick ? 25 : 100;
    s.args = "render " + shell_quote(dem) + " --samples " + std::to_string(samples) + " --directions " +
             std::to_string(directions) + (size == Size::tiny ? " --reference-azimuths 64" : "");
    s.parse = [dem, directions](const std::vector<CsvRecord>& csv, const std::string& log,
                                std::vector<ReportRow>& rows) {
        // One-time cost from the log ("visibility 0.31 s, transfer 0.12 s"), plus a frame.
        double once = kNaN;
        std::smatch m;
        if (std::regex_search(log, m, std::regex("visibility ([0-9.]+) s, transfer ([0-9.]+) s")))
            once = std::stod(m[1]) + std::stod(m[2]);
        double err = 0, frame = 0;
        int n = 0;
        for (const CsvRecord& r : csv) {
            if (std::isnan(csv_field(r, "rel_rmse"))) continue;
            err += csv_field(r, "rel_rmse");
            frame += csv_field(r, "frame_ms") / 1000.0;
            ++n;
        }
        if (n == 0) return;
        rows.push_back({"render", "directions", std::to_string(directions), directions == 32, once + frame / n,
                        err / n, "radiance_rel_rmse", dem_name(dem)});
    };
    return s;
}

// bench render with the terrain's transfer projected from its horizons (the default) and the
// log-SH path's: one-time cost plus a frame against the radiance error (the ray-traced
// reference, direct light on both sides; bench render's CSV has the shadows' error too).
Study terrain_transfer_study(const std::string& dem, Size size) {
    Study s;
    s.name = "render terrain transfer on " + dem_name(dem);
    const int samples = size == Size::tiny ? 20 : size == Size::quick ? 120 : 600;
    s.expected_s = size == Size::tiny ? 8 : size == Size::quick ? 35 : 140;
    s.args = "render " + shell_quote(dem) + " --samples " + std::to_string(samples) +
             " --terrain-transfer exact,log-sh" + (size == Size::tiny ? " --reference-azimuths 64" : "");
    s.parse = [dem](const std::vector<CsvRecord>& csv, const std::string&, std::vector<ReportRow>& rows) {
        for (const char* transfer : {"exact", "log-sh"}) {
            double once = 0, err = 0, frame = 0;
            int n = 0;
            for (const CsvRecord& r : csv) {
                if (r.at("terrain_transfer") != transfer || std::isnan(csv_field(r, "rel_rmse"))) continue;
                once = csv_field(r, "state_s");
                err += csv_field(r, "rel_rmse");
                frame += csv_field(r, "frame_ms") / 1000.0;
                ++n;
            }
            if (n == 0) continue;
            rows.push_back({"render", "terrain_transfer", transfer, std::string(transfer) == "exact", once + frame / n,
                            err / n, "radiance_rel_rmse", dem_name(dem)});
        }
    };
    return s;
}

// bench sun: the per-frame sun visibility, sweep near fields against the exact pass.
Study sun_study(const std::string& dem, Size size) {
    Study s;
    s.name = "sun shadows on " + dem_name(dem);
    s.expected_s = size == Size::tiny ? 1 : size == Size::quick ? 4 : 90;
    const std::string max_size = size == Size::tiny ? "40" : size == Size::quick ? "200" : "500";
    s.args = "sun " + shell_quote(dem) + " --max-size " + max_size + " --near-field 2,4,8,16" +
             (size == Size::full ? "" : " --frames 2 --elevations 3 15 40 --azimuths 90 225");
    s.parse = [dem](const std::vector<CsvRecord>& csv, const std::string&, std::vector<ReportRow>& rows) {
        std::map<int, std::array<double, 4>> by;  // near -> sweep s, 1 - iou, exact s, n
        for (const CsvRecord& r : csv) {
            auto& a = by[int(csv_field(r, "near_field"))];
            a[0] += csv_field(r, "sweep_ms") / 1000.0;
            a[1] += 1.0 - csv_field(r, "iou_mean");
            a[2] += csv_field(r, "exact_ms") / 1000.0;
            a[3] += 1;
        }
        double exact_s = 0;
        for (const auto& [near, a] : by) {
            rows.push_back({"render", "sun_near_field", std::to_string(near), near == 8, a[0] / a[3], a[1] / a[3],
                            "1-mask_iou_vs_exact", dem_name(dem)});
            if (near == 8) {
                rows.push_back({"render", "sun_shadows", "sweep", true, a[0] / a[3], a[1] / a[3],
                                "1-mask_iou_vs_exact", dem_name(dem)});
                exact_s = a[2] / a[3];
            }
        }
        if (exact_s > 0)
            rows.push_back({"render", "sun_shadows", "exact", false, exact_s, 0.0, "1-mask_iou_vs_exact", dem_name(dem)});
    };
    return s;
}

// bench sh --sweep: every exponentiation method and its accuracy knob, on random scenes.
Study exp_study(Size size) {
    Study s;
    s.name = "SH exponentiation";
    s.expected_s = size == Size::tiny ? 5 : size == Size::quick ? 15 : 60;
    s.args = std::string("sh --sweep --scenes ") + (size == Size::tiny ? "1" : size == Size::quick ? "2" : "16");
    s.parse = [](const std::vector<CsvRecord>& csv, const std::string&, std::vector<ReportRow>& rows) {
        // Scenes of 64 sphere caps (a mesh footprint): the case blockers make hard.
        for (const CsvRecord& r : csv) {
            if (r.at("kind") != "scene" || int(csv_field(r, "blockers")) != 64) continue;
            const std::string m = r.at("method"), p = r.at("param");
            ReportRow row{"visibility", "", "", false, csv_field(r, "ns_per_exp") * 1e-9, csv_field(r, "rms_error"),
                          "exp_rms_vs_exact", "random_scenes_64_caps"};
            const bool method_default = p == "order=8" || p == "table" || p == "threshold=1";
            if (method_default) {
                row.knob = "exp_method";
                row.value = m;
                row.is_default = m == "hybrid";
                rows.push_back(row);
            }
            if (m == "scaling_squaring" || m == "hybrid" || m == "taylor") {
                row.knob = m + "_param";
                row.value = p.substr(p.find('=') + 1);
                row.is_default = method_default;
                rows.push_back(row);
            }
        }
    };
    return s;
}

// bench sh --eps-csv: the log-epsilon floors (error only: epsilon does not change the time).
Study epsilon_study() {
    Study s;
    s.name = "log epsilon";
    s.expected_s = 12;
    s.args = std::string("sh --scenes 2 --exp-method hybrid --eps-csv");  // --csv follows: the eps CSV
    s.parse = [](const std::vector<CsvRecord>& csv, const std::string&, std::vector<ReportRow>& rows) {
        for (const CsvRecord& r : csv) {
            const std::string lobe = r.at("lobe");
            const double eps = csv_field(r, "eps");
            if (lobe == "diffuse")
                rows.push_back({"render", "brdf_log_eps", format_value(eps), std::abs(eps - 0.05) < 1e-9, kNaN,
                                csv_field(r, "rms_error"), "lobe_rms_vs_clamped_cosine", "-"});
            else if (lobe == "vis_64")
                rows.push_back({"visibility", "visibility_log_eps", format_value(eps), std::abs(eps - 0.1) < 1e-9,
                                kNaN, csv_field(r, "rms_error"), "visibility_rms_64_caps", "-"});
        }
    };
    return s;
}

// bench spheres: decomposition time and excess volume against the sphere count.
Study spheres_study(const std::string& mesh, Size size) {
    Study s;
    s.name = "sphere count on " + dem_name(mesh);
    s.expected_s = size == Size::tiny ? 1 : size == Size::quick ? 4 : 120;
    s.args = "spheres --mesh " + shell_quote(mesh) + " --large-counts 8 --subdivide 0 --counts " +
             (size == Size::tiny ? "8,16" : size == Size::quick ? "8,16,32,64,128" : "8,16,32,64,128,256,512");
    s.parse = [mesh](const std::vector<CsvRecord>& csv, const std::string&, std::vector<ReportRow>& rows) {
        for (const CsvRecord& r : csv) {
            const int count = int(csv_field(r, "count"));
            rows.push_back({"render", "sphere_count", std::to_string(count), count == 64, csv_field(r, "seconds"),
                            csv_field(r, "excess_volume_ratio"), "excess_volume_ratio", dem_name(mesh)});
        }
    };
    return s;
}

// bench visibility --whole: every device path on one DEM (its log lines, no CSV).
Study device_study(const std::string& dem, Size size) {
    Study s;
    s.name = "device paths on " + dem_name(dem);
    s.expected_s = size == Size::tiny ? 10 : size == Size::quick ? 25 : 60;
    s.writes_csv = false;
    s.args = "visibility " + shell_quote(dem) + " --whole --no-saga --window 40 --reference-directions 64 " +
             "--full-directions " + (size == Size::tiny ? "8" : "32") + " --repeats " +
             (size == Size::full ? "3" : "1");
    s.parse = [dem](const std::vector<CsvRecord>&, const std::string& log, std::vector<ReportRow>& rows) {
        const std::regex line(R"(^\s+(default|cpu|vulkan)\s+([0-9.]+) ms .*svf RMSE ([0-9.eE+-]+))");
        std::istringstream in(log);
        std::string l;
        while (std::getline(in, l)) {
            std::smatch m;
            if (std::regex_search(l, m, line))
                rows.push_back({"visibility", "device", m[1] == "default" ? "auto" : std::string(m[1]),
                                m[1] == "default", std::stod(m[2]) / 1000.0, std::stod(m[3]), "svf_rmse",
                                dem_name(dem) + " (whole DEM)"});
        }
    };
    return s;
}

// bench tiles --knobs: relief's block size, halo and far field against the level shaded whole,
// 512- against 256-px tiles, and the pyramid level of z7 and z8 (--level-bias) against level 0
// averaged (z9 on is Grenoble's level 0).
Study tile_knobs_study(const std::string& dem) {
    Study s;
    s.name = "tiles knobs on " + dem_name(dem);
    s.expected_s = 42;
    s.args = "tiles " + shell_quote(dem) + " --zoom 7-11 --knobs";
    s.parse = [dem](const std::vector<CsvRecord>& csv, const std::string&, std::vector<ReportRow>& rows) {
        for (const CsvRecord& r : csv) {
            const std::string value = r.at("value");
            std::string knob = r.at("knob");
            const bool tile_size = knob == "tile_size", level = knob.starts_with("level_bias_");
            // level_bias_zZ: one panel per zoom (their errors are against different references).
            const std::string where = level ? " (relief " + knob.substr(11) + ")" : " (relief z11)";
            if (level) knob = "level_bias";
            rows.push_back({"tiles", knob, value, csv_field(r, "is_default") == 1, csv_field(r, "seconds"),
                            csv_field(r, "rms_codes"),
                            tile_size ? "rms_srgb_codes_vs_256px_tiles"
                            : level   ? "rms_srgb_codes_vs_level0_averaged"
                                      : "rms_srgb_codes_vs_whole_level",
                            dem_name(dem) + where});
        }
    };
    return s;
}

// bench blockers --motion-only: a moving 400-sphere aircraft's per-frame sky update through the
// sphere hierarchy (threshold and tangent-plane culling) against every sphere at every texel
// (--sphere-culling none, the default).
Study culling_study(const std::string& dem, const std::string& mesh, Size size) {
    Study s;
    s.name = "sphere culling on " + dem_name(dem);
    s.expected_s = size == Size::full ? 60 : 15;
    s.writes_csv = false;
    s.args = "blockers --motion-only --mesh " + shell_quote(mesh) + " --motion-dem " + shell_quote(dem) +
             " --motion-frames " + (size == Size::full ? "8" : "2");
    s.parse = [dem](const std::vector<CsvRecord>&, const std::string& log, std::vector<ReportRow>& rows) {
        const std::regex frame(R"(^(hierarchy|flat) \([^)]*\)\s+([0-9.]+))");
        const std::regex error(R"(^culling error: sky visibility rms ([0-9.eE+-]+))");
        double tree_s = kNaN, flat_s = kNaN, rms = kNaN;
        std::istringstream in(log);
        std::string l;
        while (std::getline(in, l)) {
            std::smatch m;
            if (std::regex_search(l, m, frame)) (m[1] == "hierarchy" ? tree_s : flat_s) = std::stod(m[2]) / 1000.0;
            if (std::regex_search(l, m, error)) rms = std::stod(m[1]);
        }
        if (std::isnan(tree_s) || std::isnan(flat_s) || std::isnan(rms)) return;
        const std::string where = dem_name(dem) + " (400 spheres, per frame)";
        rows.push_back({"render", "sphere_culling", "hierarchy", false, tree_s, rms, "sky_visibility_rms_vs_no_culling", where});
        rows.push_back({"render", "sphere_culling", "none", true, flat_s, 0.0, "sky_visibility_rms_vs_no_culling", where});
    };
    return s;
}

// bench blockers at 64 spheres: what casts a mesh's sun shadow (--mesh-sun-shadow) and how many
// rays the triangles take (--mesh-sun-rays), against 256 rays through the triangles.
Study sun_caster_study(const std::string& dem, const std::string& mesh) {
    Study s;
    s.name = "mesh sun shadow on " + dem_name(dem);
    s.expected_s = 10;
    s.writes_csv = false;
    s.args = "blockers --dem " + shell_quote(dem) + " --mesh " + shell_quote(mesh) +
             " --counts 64 --sky-strata 8 --motion-frames 0";
    s.parse = [dem](const std::vector<CsvRecord>&, const std::string& log, std::vector<ReportRow>& rows) {
        const std::regex line(R"(^sun caster (spheres|triangles (\d+) rays)\s+ms\s+([0-9.]+) rmse ([0-9.eE+-]+))");
        std::istringstream in(log);
        std::string l;
        while (std::getline(in, l)) {
            std::smatch m;
            if (!std::regex_search(l, m, line)) continue;
            // Two knobs: the caster (the triangles at their default rays), and the triangles' rays.
            const bool spheres = m[1] == "spheres", is_default = l.find("(default)") != std::string::npos;
            const double seconds = std::stod(m[3]) / 1000.0, rms = std::stod(m[4]);
            const std::string where = dem_name(dem) + " (64 spheres, per frame)";
            if (spheres || is_default)
                rows.push_back({"render", "mesh_sun_shadow", spheres ? "spheres" : "triangles", !spheres, seconds, rms,
                                "sun_visible_disc_rms_vs_256_rays", where});
            if (!spheres)
                rows.push_back({"render", "mesh_sun_rays", m[2].str(), is_default, seconds, rms,
                                "sun_visible_disc_rms_vs_256_rays", where});
        }
    };
    return s;
}

// bench bounce: the bounced light's knobs, the cost on a DEM (the scene's one-time work plus a
// frame) against the error on the crop Blender Cycles rendered with 4 bounces (stored in the
// repository, tests/render/reference/).
Study bounce_study(const std::string& dem, const std::string& reference_dir, Size size) {
    Study s;
    s.name = "bounced light knobs on " + dem_name(dem);
    s.expected_s = size == Size::tiny ? 2 : size == Size::quick ? 30 : 60;
    const std::string crop = reference_dir + "/anatolia_tm90_64.tif";
    const std::string timed = size == Size::tiny ? crop : dem;
    const std::string cycles = reference_dir + "/cycles_clear_e20_a0.3_b4.exr";
    s.inputs = {crop, cycles};
    s.args = "bounce " + shell_quote(timed) + " --reference-dem " + shell_quote(crop) + " --reference " +
             shell_quote(cycles) + " --frames " +
             (size == Size::full ? "8" : "2");
    const std::string where = dem_name(timed) + " (error: Cycles crop)";
    s.parse = [where](const std::vector<CsvRecord>& csv, const std::string&, std::vector<ReportRow>& rows) {
        for (const CsvRecord& r : csv)
            rows.push_back({"render", r.at("knob"), r.at("value"), csv_field(r, "is_default") == 1,
                            csv_field(r, "once_s") + csv_field(r, "frame_ms") / 1000.0, csv_field(r, "relative_rmse"),
                            "radiance_rel_rmse_vs_cycles_4_bounces", where});
    };
    return s;
}

#ifdef TERRASHADE_HAS_GPU
// bench fly: frame time and screen-space error against the LOD goal (its log's CSV lines).
Study fly_study(const std::string& dem, double goal_px, Size size) {
    Study s;
    s.name = "fly --pixel-error " + format_value(goal_px);
    s.expected_s = size == Size::full ? 30 : 6;
    s.writes_csv = false;
    s.args = "fly " + shell_quote(dem) + " --pixel-error " + format_value(goal_px) + " --directions 8 --frames " +
             (size == Size::full ? "60 --size 960x540" : "8 --size 320x180");
    s.parse = [dem, goal_px](const std::vector<CsvRecord>&, const std::string& log, std::vector<ReportRow>& rows) {
        // The first CSV block: lod_goal_px,lod_quantile,fps_mean,frame_ms_mean,...,screen_error_px,...
        std::istringstream in(log);
        std::string l, header;
        while (std::getline(in, l)) {
            if (l.rfind("lod_goal_px,", 0) == 0) {
                header = l;
                continue;
            }
            if (header.empty() || l.empty() || !std::isdigit(static_cast<unsigned char>(l[0]))) continue;
            const auto rec = bench::read_csv_records(header + "\n" + l + "\n");
            if (rec.empty()) continue;
            const double goal = csv_field(rec[0], "lod_goal_px"), q = csv_field(rec[0], "lod_quantile");
            if (q != 0.99 || std::abs(goal - goal_px) > 1e-9) continue;
            rows.push_back({"fly", "pixel_error", format_value(goal), std::abs(goal - 2.0) < 1e-9,
                            csv_field(rec[0], "frame_ms_mean") / 1000.0, csv_field(rec[0], "screen_error_px"),
                            "screen_error_bound_px", dem_name(dem)});
            return;
        }
    };
    return s;
}
#endif

std::vector<Study> studies(const BenchReportOptions& o, Size size) {
    const std::string dem_dir = o.data + "/dem/";
    const std::string grenoble = dem_dir + "copernicus_N45E005_grenoble_500px.tif";
    std::vector<std::string> dems = {grenoble};
    if (size == Size::full) dems.push_back(dem_dir + "srtm3_N39E040_1000px.tif");
    std::vector<Study> s;
    for (const auto& d : dems) s.push_back(visibility_study(d, size));
    const std::vector<int> render_d = size == Size::tiny ? std::vector<int>{8} : std::vector<int>{8, 16, 32, 64};
    for (int d : render_d) s.push_back(render_study(grenoble, d, size));
    s.push_back(terrain_transfer_study(grenoble, size));
    for (const auto& d : dems) s.push_back(sun_study(d, size));
    s.push_back(exp_study(size));
    s.push_back(epsilon_study());
    s.push_back(spheres_study(o.data + "/meshes/c172p.ac", size));
    s.push_back(device_study(grenoble, size));
    if (size != Size::tiny) s.push_back(tile_knobs_study(grenoble));
    if (size != Size::tiny) s.push_back(culling_study(grenoble, o.data + "/meshes/c172p.ac", size));
    if (size != Size::tiny) s.push_back(sun_caster_study(dem_dir + "srtm3_N39E040_1000px.tif", o.data + "/meshes/c172p.ac"));
    s.push_back(bounce_study(grenoble, o.reference_dir, size));
#ifdef TERRASHADE_HAS_GPU
    if (size != Size::tiny)
        for (double g : {0.5, 1.0, 2.0, 4.0, 8.0}) s.push_back(fly_study(grenoble, g, size));
#endif
    if (!o.only.empty()) {
        std::vector<Study> kept;
        for (auto& st : s)
            for (const auto& w : o.only)
                if (st.name.find(w) != std::string::npos) {
                    kept.push_back(st);
                    break;
                }
        s = kept;
    }
    return s;
}

std::string self_executable() {
    std::error_code ec;
    const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) throw InputError("bench report: cannot find its own executable (/proc/self/exe)");
    return p.string();
}

void run_bench_report(const BenchReportOptions& o) {
    const Size size = o.tiny ? Size::tiny : o.quick ? Size::quick : Size::full;
    const std::filesystem::path csv_path = std::filesystem::path(o.out) / "report.csv";
    for (const std::string& f : {o.data + "/dem/copernicus_N45E005_grenoble_500px.tif", o.data + "/meshes/c172p.ac"})
        if (!std::filesystem::exists(f)) throw InputError("bench report: " + f + " not found (set --data)");
    const std::vector<Study> list = studies(o, size);
    if (list.empty()) throw InputError("bench report: --only matched no study");
    for (const Study& s : list)
        for (const std::string& f : s.inputs)
            if (!std::filesystem::exists(f))
                throw InputError("bench report: " + f + " not found (study \"" + s.name +
                                 "\"; run it from the repository, or set --reference-dir)");
    // --out DIR is made if missing (IoPlan checks it is writable), after the other checks, and
    // removed again (the folders it made, empty) if the check refuses it.
    std::error_code ec;
    std::filesystem::path made;  // the outermost folder created here
    for (std::filesystem::path p = std::filesystem::path(o.out).lexically_normal(); !p.empty() && p != p.parent_path();
         p = p.parent_path())
        if (!std::filesystem::exists(p, ec)) made = p;
    std::filesystem::create_directories(o.out, ec);
    IoPlan plan;
    plan.output("--out", csv_path.string(), {".csv"});
    try {
        plan.check();
    } catch (...) {
        if (!made.empty())  // each folder only if empty: never anything that was there before
            for (std::filesystem::path p = std::filesystem::path(o.out).lexically_normal(); !p.empty(); p = p.parent_path()) {
                std::filesystem::remove(p, ec);
                if (p == made) break;
            }
        throw;
    }
    double expected = 0;
    for (const Study& s : list) expected += s.expected_s;
    std::printf("bench report (%s): %zu studies, expected about %.0f min on 2 cores\n",
                size == Size::full ? "full" : size == Size::quick ? "quick" : "tiny", list.size(),
                std::max(1.0, expected / 60.0));
    std::fflush(stdout);

    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("terrashade-bench-report-" + std::to_string(::getpid()));
    temp_files::track_directory(dir);
    std::filesystem::create_directories(dir);
    const std::string exe = self_executable();
    std::vector<ReportRow> rows;
    ProgressBar bar("bench report", std::uint64_t(std::llround(expected)), "s");
    Stopwatch total;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const Study& s = list[i];
        const auto csv = dir / ("study" + std::to_string(i) + ".csv");
        const auto log = dir / ("study" + std::to_string(i) + ".log");
        std::string cmd = shell_quote(exe) + " " + s.args;  // exe is terrashade-bench itself
        if (s.writes_csv) cmd += " " + (s.args.ends_with("--eps-csv") ? std::string() : std::string("--csv ")) +
                                 shell_quote(csv.string());
        cmd += " > " + shell_quote(log.string()) + " 2>&1";
        Stopwatch t;
        const int rc = std::system(cmd.c_str());
        const std::string log_text = read_text(log);
        if (rc != 0) {
            std::filesystem::remove_all(dir);
            temp_files::forget_directory(dir);
            throw InputError("bench report: `terrashade bench " + s.args + "` failed:\n" + log_text);
        }
        const std::size_t before = rows.size();
        s.parse(s.writes_csv ? bench::read_csv_records(read_text(csv)) : std::vector<CsvRecord>{}, log_text, rows);
        if (!bar.enabled())
            std::printf("  %-40s %6.1f s, %zu rows\n", s.name.c_str(), t.seconds(), rows.size() - before);
        bar.advance(std::uint64_t(std::llround(s.expected_s)));
        std::fflush(stdout);
    }
    bar.finish();
    std::filesystem::remove_all(dir);
    temp_files::forget_directory(dir);

    StagedOutputs outputs;
    outputs.stage(csv_path, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out << bench::report_csv(rows);
        if (!out.flush()) throw input_error(csv_path.string(), "cannot write");
    });
    outputs.commit();
    std::printf("wrote %s (%zu rows) in %.0f s; charts: /usr/bin/python3 scripts/chart_report.py %s %s\n",
                csv_path.string().c_str(), rows.size(), total.seconds(), csv_path.string().c_str(), o.out.c_str());
}

}  // namespace

void add_bench_report_command(CLI::App& bench) {
    auto o = std::make_shared<BenchReportOptions>();
    CLI::App* cmd = bench.add_subcommand(
        "report",
        "Every speed/accuracy knob against its command's reference, in one CSV (OUT/report.csv): runs the other "
        "bench studies on crops of the shared DEMs; scripts/chart_report.py draws the charts");
    cmd->add_flag("--quick", o->quick, "Small crops and fewer repeats (under 5 minutes on 2 cores)");
    cmd->add_flag("--tiny", o->tiny)->group("");  // the CLI test: the CSV's shape in seconds
    cmd->add_option("--out", o->out, "Directory of report.csv")->capture_default_str();
    cmd->add_option("--data", o->data, "Folder holding dem/ and meshes/ (the shared data)")->capture_default_str();
    cmd->add_option("--reference-dir", o->reference_dir,
                    "Folder of the stored Blender Cycles pictures (the bounced light's study)")
        ->capture_default_str();
    cmd->add_option("--only", o->only, "Run only the studies whose name contains one of these words")
        ->delimiter(',');
    cmd->callback([o] { run_bench_report(*o); });
}

}  // namespace ts::app
