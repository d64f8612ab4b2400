// `terrashade bench bounce`: each bounced-light knob's cost against its error (docs/rendering.md,
// "Bounced light"). The cost on a DEM (the scene's one-time work and a frame, CPU); the error
// against a Blender Cycles picture of a crop with 4 bounces (tests/render/reference/, made by
// scripts/make_cycles_reference.sh: grey Lambert albedo 0.3, terrashade's clear sky with ground
// albedo 0.3, sun at azimuth 135 and elevation 20 degrees, flat Earth), rendered by terrashade
// with the same scene; compared on the crop's inner texels as tests/cli/cycles_reference_cli_test.cpp
// compares them. bench report turns its CSV into rows.
#include <malloc.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/bench/bench_command.hpp"
#include "app/bench/study/picture_agreement.hpp"
#include "app/compute_device.hpp"
#include "app/io_plan.hpp"
#include "app/render_options.hpp"
#include "core/raster/image_io_plugin/float_image_io.hpp"
#include "core/util/error.hpp"
#include "core/util/staged_outputs.hpp"
#include "core/util/stopwatch.hpp"

namespace ts::app {
namespace {

struct BenchBounceArgs {
    std::string dem;            // the cost's DEM
    std::string reference_dem;  // the crop Cycles rendered
    std::string reference;      // its picture (linear float)
    int frames = 4;
    int threads = 0;
    std::string csv;
};

// One setting of one knob; the rest at their defaults.
struct BounceCase {
    std::string knob, value;
    bool is_default = false;
    render::BounceSettings settings;
};

bool same_bounce_settings(const render::BounceSettings& x, const render::BounceSettings& y) {
    return x.bounces == y.bounces && x.sun == y.sun && x.gather.directions == y.gather.directions &&
           x.gather.radius_texels == y.gather.radius_texels && x.gather.growth == y.gather.growth;
}

std::vector<BounceCase> bounce_cases() {
    const render::BounceSettings d;
    std::vector<BounceCase> cases;
    auto add = [&](const std::string& knob, const std::string& value, auto&& change) {
        BounceCase c{knob, value, false, d};
        change(c.settings);
        c.is_default = same_bounce_settings(c.settings, d);
        cases.push_back(c);
    };
    for (int b : {0, 1, 2}) add("bounces", std::to_string(b), [&](render::BounceSettings& s) { s.bounces = b; });
    add("bounce_sun", "gather", [](render::BounceSettings& s) { s.sun = render::BounceSettings::SunPart::gather; });
    add("bounce_sun", "sh", [](render::BounceSettings& s) { s.sun = render::BounceSettings::SunPart::sh; });
    for (int n : {4, 8, 16})
        add("bounce_directions", std::to_string(n), [&](render::BounceSettings& s) { s.gather.directions = n; });
    for (int r : {16, 32, 64, 96})
        add("bounce_radius", std::to_string(r), [&](render::BounceSettings& s) { s.gather.radius_texels = r; });
    for (const char* g : {"1.2", "1.3", "1.4"})
        add("bounce_growth", g, [&](render::BounceSettings& s) { s.gather.growth = std::stod(g); });
    return cases;
}

// The scene's options as `render DEM --colors grey:0.3 --sky clear:albedo=0.3 --no-curvature --cpu`.
RenderArgs bounce_case_args(const std::string& dem, const BounceCase& c, int threads) {
    RenderArgs r;
    r.dem.files = {dem};
    r.colors.colors = "grey:0.3";
    r.sky = "clear:albedo=0.3";
    r.no_curvature = true;
    r.device.cpu = true;
    r.threads = threads;
    r.bounce = c.settings;
    return r;
}

// Cycles' mesh ends at the crop: compared are the texels at least this far inside.
constexpr int kBounceCropBorder = 4;

void run_bench_bounce(const BenchBounceArgs& a) {
    IoPlan plan;
    plan.input("DEM", a.dem)
        .input("--reference-dem", a.reference_dem)
        .input("--reference", a.reference)
        .output("--csv", a.csv, {".csv"});
    plan.check();
    if (a.frames < 1) throw InputError("bench bounce: --frames must be >= 1");
#ifdef M_MMAP_THRESHOLD
    // Every setting pays for its memory as a fresh `render` does: with glibc's threshold grown by
    // the first scene's frees, later scenes took their arrays from the heap without page faults
    // and their one-time work ran up to 2.5x faster (the bounce 0.08 s against 0.20 s).
    mallopt(M_MMAP_THRESHOLD, 128 * 1024);
#endif
    const raster::FloatImage cycles = raster::read_float_image(a.reference);
    if (cycles.rgb.size() != std::size_t(cycles.width) * std::size_t(cycles.height) * 3)
        throw input_error(a.reference, "not an RGB picture (--reference: Cycles' linear float render)");
    const std::vector<double> reference =
        bench::inner_luminance(cycles.width, cycles.height, cycles.rgb.data(), kBounceCropBorder);
    const dem::Dem timing_dem = load_dem_input(DemInput{.files = {a.dem}});
    const dem::Dem crop = load_dem_input(DemInput{.files = {a.reference_dem}});
    if (crop.width != cycles.width || crop.height != cycles.height)
        throw InputError("bench bounce: " + a.reference + " is not the size of " + a.reference_dem);

    std::string csv = "knob,value,is_default,once_s,frame_ms,relative_rmse,correlation,bias\n";
    std::printf("%-18s %-7s %9s %9s %9s %9s %8s\n", "knob", "value", "once s", "frame ms", "rel RMSE", "corr", "bias");
    // The default appears under every knob: each distinct setting is measured once.
    struct Measured {
        render::BounceSettings settings;
        double once_s, frame_ms;
        bench::PictureAgreement error;
    };
    std::vector<Measured> measured;
    auto measure = [&](const BounceCase& c) {
        // Cost: the scene's one-time work, then frames of a sun moving over the sky.
        const RenderArgs timing = bounce_case_args(a.dem, c, a.threads);
        render::SceneOptions options = scene_options(timing);
        const ComputeDevice device(timing.device);
        device.apply(options);
        Measured m{c.settings, 0, 0, {}};
        Stopwatch t;
        {
            render::Scene scene(timing_dem, options);
            m.once_s = t.seconds();
            render::LinearImage image;
            scene.render(render::SunState{135, 20}, image);  // warm-up (first touch)
            t.restart();
            for (int k = 0; k < a.frames; ++k)
                scene.render(render::SunState{90.0 + 180.0 * k / a.frames, 10.0 + 40.0 * k / a.frames}, image);
            m.frame_ms = t.milliseconds() / a.frames;
        }
        // Error: the crop under Cycles' sun and sky.
        const RenderArgs ref_args = bounce_case_args(a.reference_dem, c, a.threads);
        render::SceneOptions ref_options = scene_options(ref_args);
        device.apply(ref_options);
        render::Scene scene(crop, ref_options);
        render::LinearImage image;
        scene.render(render::SunState{135, 20}, image);
        if (image.width != cycles.width || image.height != cycles.height)
            throw std::logic_error("bench bounce: the map is not the crop's size");
        m.error = bench::picture_agreement(
            reference, bench::inner_luminance(image.width, image.height, &image.rgb.data()->x, kBounceCropBorder));
        return m;
    };
    for (const BounceCase& c : bounce_cases()) {
        auto it = std::find_if(measured.begin(), measured.end(),
                               [&](const Measured& m) { return same_bounce_settings(m.settings, c.settings); });
        if (it == measured.end()) it = measured.insert(measured.end(), measure(c));
        const double once_s = it->once_s, frame_ms = it->frame_ms;
        const bench::PictureAgreement& e = it->error;
        std::printf("%-18s %-7s %9.3f %9.2f %8.2f%% %9.5f %+7.2f%%%s\n", c.knob.c_str(), c.value.c_str(), once_s,
                    frame_ms, 100 * e.relative_rmse, e.correlation, 100 * e.bias, c.is_default ? " (default)" : "");
        std::fflush(stdout);
        char row[256];
        std::snprintf(row, sizeof row, "%s,%s,%d,%.4f,%.3f,%.6f,%.6f,%.6f\n", c.knob.c_str(), c.value.c_str(),
                      c.is_default ? 1 : 0, once_s, frame_ms, e.relative_rmse, e.correlation, e.bias);
        csv += row;
    }
    if (!a.csv.empty()) {
        StagedOutputs outputs;
        outputs.stage(a.csv, [&](const std::filesystem::path& tmp) {
            std::ofstream out(tmp, std::ios::binary);
            out << csv;
            if (!out.flush()) throw input_error(a.csv, "cannot write");
        });
        outputs.commit();
    }
}

}  // namespace

void add_bench_bounce_command(CLI::App& bench) {
    auto a = std::make_shared<BenchBounceArgs>();
    CLI::App* cmd = bench.add_subcommand(
        "bounce", "Bounced light: each knob's cost on a DEM against its error on a crop Blender Cycles rendered");
    cmd->add_option("DEM", a->dem, "DEM the cost is measured on")->required();
    cmd->add_option("--reference-dem", a->reference_dem, "The crop Cycles rendered (tests/render/reference/)")
        ->required();
    cmd->add_option("--reference", a->reference,
                    "Cycles' picture of it: 4 bounces, grey albedo 0.3, the clear sky with ground albedo 0.3, "
                    "sun at azimuth 135 and elevation 20 degrees")
        ->required();
    cmd->add_option("--frames", a->frames, "Frames timed per setting")->capture_default_str();
    cmd->add_option("--threads", a->threads, "Worker threads (0 = one per core)")->capture_default_str();
    cmd->add_option("--csv", a->csv, "Write the rows as CSV (knob,value,is_default,once_s,frame_ms,relative_rmse,...)");
    cmd->callback([a] { run_bench_bounce(*a); });
}

}  // namespace ts::app
