// `terrashade render`: one shaded picture of a DEM under the sun and sky at a time (or a sun
// position given directly), as a map on the DEM's grid or a perspective camera view.
// Pipeline and formulas: docs/rendering.md.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "app/compute_device.hpp"
#include "app/job_memory.hpp"
#include "app/options/sun_options.hpp"
#include "app/render_options.hpp"
#include "core/light/utc_time.hpp"
#include "core/raster/raster_writer.hpp"
#include "core/util/error.hpp"
#include "core/util/progress_bar.hpp"
#include "core/util/staged_outputs.hpp"
#include "core/visibility/sun_visibility.hpp"
#include "core/util/stopwatch.hpp"
#include "core/raster/image_writer_registry.hpp"

namespace ts::app {
namespace {

struct RenderCommandArgs {
    RenderArgs render;
    std::string time;
    std::optional<double> sun_azimuth, sun_elevation;
    std::string out;
    std::string sun_visibility;
};

void run_render(const RenderCommandArgs& a) {
    // Every check that needs no DEM first.
    const bool by_time = !a.time.empty();
    const bool by_angles = a.sun_azimuth.has_value() || a.sun_elevation.has_value();
    if (by_time == by_angles)
        throw InputError("render: give either --time or both --sun-azimuth and --sun-elevation");
    if (by_angles && !(a.sun_azimuth && a.sun_elevation))
        throw InputError("render: --sun-azimuth and --sun-elevation go together");
    std::optional<light::UtcTime> time;
    if (by_time) time = light::parse_utc_time(a.time);
    render::SceneOptions options = scene_options(a.render);
    const render::Exposure exposure = exposure_of(a.render);
    IoPlan plan;
    plan_render_inputs(plan, a.render, options);
    plan.output("--out", a.out, raster::picture_extensions());
    plan.output("--sun-visibility", a.sun_visibility, raster::float_raster_extensions());
    plan.check();

    const dem::Dem dem = load_dem_input(a.render.dem);
    warn_if_single_line(dem);
    attach_meshes(a.render, dem, options);
    const render::SunState sun = time ? render::sun_at_dem_centre(dem, *time) : render::SunState{*a.sun_azimuth, *a.sun_elevation};
    const render::SunState grid_sun = render::sun_on_grid(sun, dem.georef.grid_azimuth_of_north_deg());
    apply_max_error(a.render, dem, {grid_sun}, options);
    const int directions = options.renderer.directions;
    check_job_memory("render of " + std::to_string(dem.width) + "x" + std::to_string(dem.height) + " texels",
                     render_peak_bytes(std::uint64_t(dem.width) * dem.height, directions, !options.meshes.empty()),
                     "use --crop, or fewer --directions (4 bytes per texel each)");
    const ComputeDevice device(a.render.device);  // before the scene: it must outlive it
    device.apply(options);
    std::unique_ptr<render::Scene> scene;
    {
        ProgressBar bar("visibility", std::uint64_t(dem.width) * dem.height * std::uint64_t(directions), "rays");
        render::SceneOptions with_bar = options;
        with_bar.renderer.progress = &bar;
        scene = std::make_unique<render::Scene>(dem, with_bar);
    }
    print_stages(a.render, *scene);
    if (sun.elevation_deg < -0.27)
        std::fprintf(stderr, "terrashade: warning: the sun is below the horizon (elevation %.2f deg): sky light only\n",
                     sun.elevation_deg);

    const Stopwatch t1;
    render::LinearImage image;
    scene->render(grid_sun, image);
    const double frame_s = t1.seconds();

    // Both outputs change together at the end, or neither does.
    StagedOutputs outputs;
    double scale = 1;
    outputs.stage(a.out, [&](const std::filesystem::path& tmp) {
        scale = render::write_image(tmp.string(), image, exposure, scene->target().georef());
    });
    if (!a.sun_visibility.empty()) {
        // The renderer sweeps only when the sky has a sun (an overcast sky has none); the file
        // is geometry, so sweep here then.
        const light::Rgb e = scene->last_sky()->sun().irradiance;
        std::vector<float> swept;
        if (!(e.x > 0 || e.y > 0 || e.z > 0)) {
            visibility::SunVisibilityOptions so;
            so.curvature = options.renderer.curvature;
            so.threads = options.renderer.threads;
            swept = visibility::sun_visibility(scene->grid(), grid_sun.azimuth_deg, grid_sun.elevation_deg, so);
        }
        outputs.stage(a.sun_visibility, [&](const std::filesystem::path& tmp) {
            raster::write_float_raster(tmp, dem.width, dem.height, 1,
                                       swept.empty() ? scene->renderer().sun_visibility().data() : swept.data(),
                                       dem.georef, {"sun_visibility: visible fraction of the sun disc"});
        });
    }
    outputs.commit();

    std::printf("sun: azimuth %.2f deg, elevation %.2f deg%s\n", sun.azimuth_deg, sun.elevation_deg,
                time ? (" at " + light::format_utc_time(*time)).c_str() : "");
    if (scene->grid_north_deg() != 0.0)
        std::printf("grid: true north lies %+.2f deg from the grid's north at the DEM's centre (the sun at %.2f deg "
                    "on the grid)\n",
                    scene->grid_north_deg(), grid_sun.azimuth_deg);
    std::printf("sky: %s\n", scene->last_sky()->describe().c_str());
    if (scene->camera()) std::printf("camera: %s\n", render::format_camera(*scene->camera()).c_str());
    const render::HorizonSkyLight* horizon_sky = scene->state().horizon_sky();
    const std::string sky_light = horizon_sky ? "sky light over the horizons in " +
                                                    std::to_string(horizon_sky->sectors()) + " sectors"
                                              : std::string("sky light through SH");
    std::printf("visibility %.3f s + transfer %.3f s (%d directions; bounced light %.3f s of it, %d bounce%s; %s), "
                "frame %.3f s, on %s\n",
                scene->state().visibility_seconds(), scene->state().transfer_seconds(), directions,
                scene->state().bounce_seconds(), scene->state().options().bounce.bounces,
                scene->state().options().bounce.bounces == 1 ? "" : "s", sky_light.c_str(), frame_s,
                device.name().c_str());
    if (!raster::written_as(a.out, raster::ImageWriter::exr))
        std::printf("exposure: %s (scale %.4g)\n", exposure.automatic ? "auto" : a.render.exposure.c_str(), scale);
    if (const render::ReliefContrastApplied rc = scene->last_relief_contrast(); rc.k != 1.0) {
        char softened[96] = "";
        if (rc.albedo_factor != 1.0)
            std::snprintf(softened, sizeof softened, ", the land colours' contrast to %.2f of --albedo-contrast",
                          rc.albedo_factor);
        std::printf("relief contrast: the shading stretched %.2fx in stops%s (--relief-contrast %s; 1 = physical)\n",
                    rc.k, softened, a.render.relief_contrast.c_str());
    }
    std::printf("wrote %s (%dx%d)\n", a.out.c_str(), image.width, image.height);
    if (!a.sun_visibility.empty()) std::printf("wrote %s\n", a.sun_visibility.c_str());
}

}  // namespace

void add_render_command(CLI::App& root) {
    auto a = std::make_shared<RenderCommandArgs>();
    CLI::App* cmd = root.add_subcommand(
        "render",
        "Shaded picture of a DEM under the real sun and sky: a map on the DEM grid or a perspective view "
        "(docs/rendering.md). Sun shadows from the exact horizon, sky light through log-SH visibility.");
    add_render_options(*cmd, a->render);
    add_sun_options(*cmd, a->time, a->sun_azimuth, a->sun_elevation);
    cmd->add_option("-o,--out", a->out, "Output: .png / .tif (8-bit sRGB; a map .tif is georeferenced) or .exr (linear)")
        ->required();
    cmd->add_option("--sun-visibility", a->sun_visibility,
                    "Also write the sun's visible fraction per texel (0..1) as a float32 GeoTIFF");
    cmd->callback([a] { run_render(*a); });
}

}  // namespace ts::app
