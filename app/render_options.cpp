#include "app/render_options.hpp"

#include <charconv>
#include <cstdlib>
#include <cstdio>
#include <cmath>
#include <functional>
#include <optional>
#include <string_view>

#include "app/mesh_max_error.hpp"
#include "app/options/bounce_option.hpp"
#include "app/options/directions_option.hpp"
#include "app/options/max_error_option.hpp"
#include "app/options/sky_option.hpp"
#include "app/options/threads_option.hpp"
#include "core/geo/crs.hpp"
#include "core/quality/blocker_quality.hpp"
#include "core/quality/radiance_quality.hpp"
#include "core/quality/visibility_quality.hpp"
#include "core/visibility/visibility_grid.hpp"

#include "core/sh/exp_method.hpp"
#include "core/util/error.hpp"
#include "core/visibility/sun_visibility.hpp"
#include "app/options/size_option.hpp"
#include "app/options/within_range.hpp"

namespace ts::app {

void add_render_options(CLI::App& cmd, RenderArgs& a) {
    add_dem_input_options(cmd, a.dem);
    add_sky_option(cmd, a.sky);
    cmd.add_option("--view", a.view, "map: top-down on the DEM grid; perspective: a camera view")
        ->capture_default_str()
        ->check(CLI::IsMember({"map", "perspective"}));
    cmd.add_option("--camera", a.camera,
                   "Perspective camera lon,lat,height,heading,pitch,fov (degrees; height in metres above the DEM "
                   "datum; heading clockwise from north; pitch < 0 looks down; horizontal fov). Default: an oblique "
                   "view towards the DEM's centre from the south-south-west, just beyond its southern edge "
                   "(docs/rendering.md)");
    cmd.add_option("--size", a.size,
                   "Output WIDTHxHEIGHT: perspective default 960x540; map default the DEM grid (else resampled); "
                   "--extent default 512 on the longer side, the extent's aspect");
    cmd.add_option("--extent", a.extent,
                   "A map of this extent instead of the DEM grid: XMIN,YMIN,XMAX,YMAX in --extent-crs (north up; "
                   "pixels off the DEM or over voids are transparent; a .tif is georeferenced in that CRS)");
    cmd.add_option("--extent-crs", a.extent_crs,
                   "CRS of --extent: EPSG:3857 (Web Mercator), EPSG:4326 (lon/lat), any EPSG code, PROJ string or "
                   "WKT (default: the DEM's CRS)");
    cmd.add_option("--exposure", a.exposure,
                   "EV100 number (e.g. 14.5 for a sunlit scene) or auto (log-average luminance to middle grey)")
        ->capture_default_str();
    add_colors_options(cmd, a.colors);
    cmd.add_option("--materials", a.materials,
                   "A land-cover GeoTIFF of ESA WorldCover class codes, resampled to the DEM by georeferencing: its "
                   "classes (forest, water, snow, ...) replace --colors where it has one");
    cmd.add_option("--albedo", a.albedo,
                   "RGB orthophoto GeoTIFF (8-bit sRGB) giving the albedo of every land texel it covers");
    cmd.add_option("--relief-contrast", a.relief_contrast,
                   "Maps: stretch the shading (not the colours) k times in stops, alike under sun and sky: 1 (the "
                   "default: the physical picture), k in 1..16 (e.g. 1.5 for print), or auto (k from the picture: a "
                   "1.5-stop spread of the shading, at most 8x; measured land colours compressed by another 1/k)")
        ->capture_default_str();
    cmd.add_option("--dither", a.dither,
                   "Dither the 8-bit output against banding: auto (perspective views, whose skies are smooth "
                   "gradients), on, off")
        ->capture_default_str()
        ->check(CLI::IsMember({"auto", "on", "off"}));
    cmd.add_option("--albedo-contrast", a.albedo_contrast,
                   "How much of the land albedos' contrast (brightness and tint) to keep, 0..1: 1 = physical "
                   "albedos (a land-cover map under soft light), 0 = land all of one colour; snow and water keep theirs")
        ->capture_default_str()
        ->check(within(0.0, 1.0));
    add_directions_option(cmd, a.directions)->each([&a](const std::string&) { a.quality_flags_given.push_back("--directions"); });
    cmd.add_flag("--no-curvature", a.no_curvature, "Ignore Earth curvature (default: d^2/(2 R_eff) with refraction)");
    cmd.add_option("--haze-km", a.haze_km,
                   "Perspective: aerial haze distance (transmittance exp(-d/haze)); 0 = none")
        ->capture_default_str()
        ->check(within(0.0, 1e6));
    cmd.add_option("--shadow-detail", a.shadow_detail,
                   "Perspective views and magnified maps: sun shadows found per pixel by a ray towards the sun "
                   "(pixel), or blended from the texels' (texel: a texel-wide, stepped edge; cheaper per frame)")
        ->capture_default_str()
        ->check(CLI::IsMember({"pixel", "texel"}));
    cmd.add_option("--edge-samples", a.edge_samples,
                   "Perspective: N x N rays across each pixel of the terrain's silhouette against the sky or "
                   "against far terrain, each surface weighed by its share (1 = one ray: stair-stepped edges)")
        ->capture_default_str()
        ->check(within(1, 16));
    cmd.add_option("--exp-method", a.exp_method, "SH exponentiation (" + sh::exp_method_choices() + ")")
        ->capture_default_str();
    cmd.add_flag("--no-band-correction", a.no_band_correction,
                 "Keep the diffuse transfer as exponentiated (default: scaled per SH band so open ground gets the exact projected cosine; docs/rendering.md)");
    cmd.add_option("--terrain-transfer", a.terrain_transfer,
                   "The terrain's sky transfer: exact (projected from its horizons) or log-sh (the log-SH "
                   "visibility's exponential, whose floor lets ~10% of the blocked sky through; docs/rendering.md)")
        ->capture_default_str()
        ->check(CLI::IsMember({"exact", "log-sh"}));
    add_sky_light_options(cmd, a.sky_light);
    add_device_options(cmd, a.device);
    cmd.add_option("--sun-shadows", a.sun_shadows,
                   "Per-frame sun shadows: sweep (fast, shadow heights along the sweep lines) or exact (the "
                   "reference horizon sweep in the sun's azimuth; docs/accuracy.md)")
        ->capture_default_str()
        ->check(CLI::IsMember({"sweep", "exact"}))
        ->each([&a](const std::string&) { a.quality_flags_given.push_back("--sun-shadows"); });
    add_bounce_options(cmd, a.bounce);
    add_max_error_option(cmd, a.max_error);
    add_threads_option(cmd, a.threads);
    add_mesh_options(cmd, a.meshes);
}

render::SceneOptions scene_options(const RenderArgs& a) {
    if (a.max_error) {
        check_max_error(a.max_error, a.quality_flags_given.empty() ? "" : a.quality_flags_given.front());
        if (!a.meshes.spheres.empty())
            throw InputError("--max-error chooses --spheres itself; drop one of them");
    }
    render::SceneOptions o;
    o.sky = light::parse_sky_options(a.sky);
    o.view = a.view == "perspective" ? render::ViewKind::perspective : render::ViewKind::map;
    if (!a.camera.empty()) {
        if (o.view != render::ViewKind::perspective) throw InputError("--camera needs --view perspective");
        o.camera = render::parse_camera(a.camera);
    }
    if (!a.size.empty()) {
        int w = 0, h = 0;
        parse_size(a.size, SizeRange{1, 16384, "1280x720"}, w, h);
        if (o.view == render::ViewKind::perspective)
            o.perspective.width = w, o.perspective.height = h;
        else
            o.map_width = w, o.map_height = h;
    }
    if (!a.extent_crs.empty() && a.extent.empty()) throw InputError("--extent-crs goes with --extent");
    if (!a.extent.empty()) {
        if (o.view != render::ViewKind::map) throw InputError("--extent: a map view only (drop --view perspective)");
        render::ExtentRequest e;
        double v[4];
        std::string_view rest = a.extent;
        for (int i = 0; i < 4; ++i) {
            const auto comma = rest.find(',');
            const std::string_view item = rest.substr(0, comma);
            const auto [p, ec] = std::from_chars(item.data(), item.data() + item.size(), v[i]);
            if (ec != std::errc() || p != item.data() + item.size() || item.empty() || (i < 3) == (comma == rest.npos))
                throw InputError("--extent " + a.extent + ": give four numbers XMIN,YMIN,XMAX,YMAX");
            rest = comma == rest.npos ? std::string_view() : rest.substr(comma + 1);
        }
        e.x0 = v[0], e.y0 = v[1], e.x1 = v[2], e.y1 = v[3];
        if (!(e.x1 > e.x0 && e.y1 > e.y0))
            throw InputError("--extent " + a.extent + ": XMIN < XMAX and YMIN < YMAX, please");
        e.crs = a.extent_crs;
        if (o.map_width > 0) {
            e.width = o.map_width, e.height = o.map_height;
        } else {
            const double aspect = (e.x1 - e.x0) / (e.y1 - e.y0);
            e.width = aspect >= 1 ? 512 : std::max(1, int(std::lround(512 * aspect)));
            e.height = aspect >= 1 ? std::max(1, int(std::lround(512 / aspect))) : 512;
        }
        if (!e.crs.empty()) geo::Crs::from_definition(e.crs);  // an unknown CRS fails before any work
        o.extent = e;
        o.view = render::ViewKind::extent;
    }
    if (a.materials == "rule")
        throw InputError("--materials rule: materials are no longer guessed from height and slope; colours come from "
                         "--colors, snow from --snow-line, land cover from a WorldCover GeoTIFF (docs/colors.md)");
    o.materials = a.materials;
    o.colors = color_design(a.colors);
    o.albedo_contrast = a.albedo_contrast;
    o.relief_contrast = parse_relief_contrast(a.relief_contrast);
    o.albedo = a.albedo;
    o.renderer.directions = a.directions;
    o.renderer.curvature = !a.no_curvature;
    o.renderer.exp_method = sh::parse_exp_method(a.exp_method);
    o.renderer.band_correction = !a.no_band_correction;
    o.renderer.terrain_transfer = a.terrain_transfer == "log-sh" ? render::RendererOptions::TerrainTransfer::log_sh
                                                                 : render::RendererOptions::TerrainTransfer::exact;
    o.renderer.sky_light = sky_light_settings(a.sky_light);
    o.renderer.threads = a.threads;
    o.renderer.sun_method = visibility::parse_sun_method(a.sun_shadows);
    o.renderer.bounce = a.bounce;
    check_bounce_options(o.renderer.bounce);  // before any heavy work
    o.perspective.haze_distance_m = a.haze_km * 1000.0;
    o.perspective.pixel_sun_shadows = a.shadow_detail == "pixel";
    o.perspective.edge_samples = a.edge_samples;
    parse_mesh_specs(a.meshes);  // everything about --mesh that needs no DEM, checked now
    o.blocker_options = blocker_options(a.meshes);
    o.mesh_terrain_shadow = !a.meshes.no_mesh_terrain_shadow;
    o.mesh_self_shadow = !a.meshes.no_mesh_self_shadow;
    return o;
}

void plan_render_inputs(IoPlan& plan, const RenderArgs& a, const render::SceneOptions& o) {
    plan.inputs("DEM", a.dem.files);
    plan.input("--sky", o.sky.hdr_path);
    plan.input("--materials", o.materials);
    plan_colors_input(plan, a.colors);
    plan.input("--albedo", o.albedo);
    for (const MeshSpec& m : parse_mesh_specs(a.meshes)) plan.input("--mesh", m.file);
}

void attach_meshes(const RenderArgs& a, const dem::Dem& dem, render::SceneOptions& o) {
    o.meshes = load_scene_meshes(parse_mesh_specs(a.meshes), dem, a.meshes, a.max_error.has_value(), a.device.verbose);
}

void apply_max_error(const RenderArgs& a, const dem::Dem& dem, const std::vector<render::SunState>& suns,
                     render::SceneOptions& o) {
    if (!a.max_error) return;
    const visibility::VisibilityGrid grid(dem);
    quality::RadianceScene scene;
    scene.roughness = quality::mean_tan_slope(grid.view());
    for (const render::SunState& s : suns) scene.sun_elevations_deg.push_back(s.elevation_deg);
    // With meshes, the terrain's setting and the spheres together: the cheapest setting that
    // leaves the meshes a budget some sphere count meets, then the fewest spheres under it.
    std::optional<MeshErrorModel> meshes;
    std::function<bool(double)> meshes_fit;
    const auto count_for = [&meshes](double budget) {
        return quality::choose_sphere_count(budget, [&meshes](int n) { return meshes->error(n); });
    };
    if (!o.meshes.empty()) {
        meshes.emplace(dem, grid.view(), o.meshes, suns, a.meshes);
        meshes_fit = [&count_for](double budget) { return count_for(budget).met; };
    }
    const quality::RadianceChoice c = quality::choose_radiance(*a.max_error, scene, meshes_fit);
    o.renderer.directions = c.directions;
    o.renderer.sun_method = c.exact_sun ? visibility::SunMethod::exact : visibility::SunMethod::sweep;
    std::printf("%s\n", max_error_line(c.reason).c_str());
    if (meshes) {
        const double budget = *a.max_error - c.predicted_error;
        const quality::SphereCountChoice n = count_for(budget);
        for (std::size_t m = 0; m < o.meshes.size(); ++m) o.meshes[m].model_spheres = meshes->spheres(m, n.spheres).spheres;
        std::printf("%s\n", mesh_choice_line(n, meshes->terms(n.spheres), meshes->picture_area_m2(), o.meshes.size(), budget).c_str());
        if (o.view != render::ViewKind::map)
            std::printf("--max-error: the meshes' share is predicted for the map of the DEM; a perspective view frames "
                        "the shadows differently\n");
    }
    std::fflush(stdout);
}

void print_stages(const RenderArgs& a, const render::Scene& scene) {
    for (const std::string& w : scene.warnings()) std::fprintf(stderr, "terrashade: warning: %s\n", w.c_str());
    for (const auto& lit : scene.mesh_lighting())
        std::printf("mesh %s: drawn lit per vertex (%zu corners, %zu distinct points), %.3f s\n",
                    lit->mesh().name.c_str(), lit->mesh().corners(), lit->distinct_points(), lit->seconds());
    if (const render::MeshView* mv = scene.mesh_view())
        std::printf("meshes cover %zu pixels of the view\n", mv->covered_pixels());
    if (!a.device.verbose) return;
    bool blockers_on_device = false;
    for (const visibility::VisibilityStage& s : scene.state().visibility_stages()) {
        std::printf("stage: %s on %s, %.3f s\n", s.label.c_str(), s.path.c_str(), s.seconds);
        blockers_on_device |= s.label.rfind("sphere blockers", 0) == 0 && s.path != "cpu";
    }
    if (!scene.blockers().empty() && scene.state().visibility_path() != "cpu")
        std::printf("stage: the mesh blockers' %s are computed on the CPU (docs/gpu.md)\n",
                    blockers_on_device ? "sun shadows" : "log-SH and sun shadows");
}

render::ReliefContrast parse_relief_contrast(const std::string& text) {
    render::ReliefContrast rc;
    if (text == "auto") return rc;
    char* end = nullptr;
    const double k = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !(k >= 1.0) || !(k <= 16.0))
        throw InputError("--relief-contrast: '" + text + "' is not auto or a number in [1, 16]");
    rc.automatic = false;
    rc.k = k;
    return rc;
}

render::Exposure exposure_of(const RenderArgs& a) {
    render::Exposure e = render::parse_exposure(a.exposure);
    // auto: perspective views, whose skies are smooth gradients; maps stay undithered so that
    // the same ground gives the same bytes in every crop, extent and tile.
    e.dither = a.dither == "on" || (a.dither == "auto" && a.view == "perspective");
    return e;
}

}  // namespace ts::app
