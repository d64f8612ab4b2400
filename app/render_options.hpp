#pragma once
// The options `render`, `relight` and `bench relight` share (app/render_command.cpp,
// app/relight_command.cpp, app/bench/bench_relight_command.cpp): the DEM, sky, view, materials,
// exposure and quality knobs, and their conversion to a render::SceneOptions.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/compute_device.hpp"
#include "app/dem_input.hpp"
#include "app/io_plan.hpp"
#include "app/mesh_options.hpp"
#include "app/options/colors_option.hpp"
#include "app/options/sky_light_option.hpp"
#include "core/render/render_scene.hpp"

namespace ts::app {

struct RenderArgs {
    DemInput dem;
    std::string sky = "clear";
    std::string view = "map";
    std::string camera;
    std::string size;
    std::string extent;      // --extent XMIN,YMIN,XMAX,YMAX (a map of that extent)
    std::string extent_crs;  // --extent-crs (default: the DEM's CRS)
    std::string exposure = "auto";
    std::string materials;   // --materials: a WorldCover land-cover GeoTIFF
    ColorsArgs colors;       // --colors, --snow-line (app/options/colors_option.hpp)
    std::string albedo;
    double albedo_contrast = render::kDefaultAlbedoContrast;
    std::string dither = "auto";
    // auto | a number >= 1; 1 (the physical picture) by default for single pictures and
    // sequences alike: a map correlates with a path tracer's, under sun and sky (docs/colors.md).
    std::string relief_contrast = "1";
    int directions = 32;
    bool no_curvature = false;
    DeviceArgs device;                    // --device, --cpu, --verbose (app/compute_device.hpp)
    double haze_km = 250.0;
    std::string shadow_detail = "pixel";  // --shadow-detail pixel|texel (PerspectiveOptions::pixel_sun_shadows)
    int edge_samples = 4;                 // --edge-samples N (PerspectiveOptions::edge_samples)
    std::string exp_method = "scaling_squaring";
    bool no_band_correction = false;
    std::string terrain_transfer = "exact";  // exact | log-sh
    SkyLightArgs sky_light;                  // --sky-light, --sky-sectors (app/options/sky_light_option.hpp)
    std::string sun_shadows = "sweep";  // --sun-shadows sweep|exact (RendererOptions::sun_method)
    render::BounceSettings bounce;        // --bounces, --bounce-directions, --bounce-radius
    int threads = 0;
    MeshArgs meshes;  // --mesh, --at, ... (app/mesh_options.hpp)
    // --max-error E: choose --directions and --sun-shadows for a relative radiance error E
    // (core/quality/radiance_quality.hpp); the quality flags given explicitly, which conflict.
    std::optional<double> max_error;
    std::vector<std::string> quality_flags_given;
};

// Adds the shared options to `cmd` (not the sun/time or output options).
void add_render_options(CLI::App& cmd, RenderArgs& args);

// Parses and checks everything that can be checked before reading the DEM.
render::SceneOptions scene_options(const RenderArgs& args);
render::Exposure exposure_of(const RenderArgs& args);
// "auto" or k in [1, 16]; throws ts::InputError otherwise.
render::ReliefContrast parse_relief_contrast(const std::string& text);
// Adds the files these options read (DEMs, an HDR sky, a land-cover map, an orthophoto) to `plan`.
void plan_render_inputs(IoPlan& plan, const RenderArgs& args, const render::SceneOptions& options);
// After the DEM is read: the meshes of --mesh placed on it, imported, their spheres from the
// cache, into options.meshes (InputError for a mesh off the DEM or a bad mesh file).
void attach_meshes(const RenderArgs& args, const dem::Dem& dem, render::SceneOptions& options);
// --max-error: once the DEM, the meshes and the suns are known, the cheapest directions and sun
// shadows predicted under E for this terrain and, with meshes, the fewest spheres that keep the
// terrain's prediction plus the meshes' under E (app/mesh_max_error.hpp), set in `options`;
// prints the chosen lines. Does nothing without --max-error. (E <= 0 and explicit --directions,
// --sun-shadows or --spheres are refused earlier, by scene_options.)
void apply_max_error(const RenderArgs& args, const dem::Dem& dem, const std::vector<render::SunState>& suns,
                     render::SceneOptions& options);
// --verbose: each visibility stage and where it ran (the mesh blockers' on the CPU).
void print_stages(const RenderArgs& args, const render::Scene& scene);

}  // namespace ts::app
