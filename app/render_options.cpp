#include "app/render_options.hpp"

#include <charconv>

#include "core/sh/exp_method.hpp"
#include "core/util/error.hpp"
#include "core/visibility/sun_visibility.hpp"

namespace ts::app {
namespace {

void parse_size(const std::string& text, int& w, int& h) {
    const auto x = text.find('x');
    auto number = [&](std::string_view s, int& out) {
        const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
        return ec == std::errc() && p == s.data() + s.size() && out >= 1 && out <= 16384;
    };
    if (x == std::string::npos || !number(std::string_view(text).substr(0, x), w) ||
        !number(std::string_view(text).substr(x + 1), h))
        throw InputError("--size " + text + ": give WIDTHxHEIGHT, each 1..16384 (e.g. 1280x720)");
}

}  // namespace

void add_render_options(CLI::App& cmd, RenderArgs& a) {
    add_dem_input_options(cmd, a.dem);
    cmd.add_option("--sky", a.sky,
                   "Sky: clear[:turbidity=T,albedo=A] | overcast[:brightness=B] | PATH.exr|PATH.hdr "
                   "(or hdr:PATH[,rotation=DEG,scale=S]) (docs/lighting.md)")
        ->capture_default_str();
    cmd.add_option("--view", a.view, "map: top-down on the DEM grid; perspective: a camera view")
        ->capture_default_str()
        ->check(CLI::IsMember({"map", "perspective"}));
    cmd.add_option("--camera", a.camera,
                   "Perspective camera lon,lat,height,heading,pitch,fov (degrees; height in metres above the DEM "
                   "datum; heading clockwise from north; pitch < 0 looks down; horizontal fov). Default: an oblique "
                   "view from beyond the DEM's south-west corner (docs/rendering.md)");
    cmd.add_option("--size", a.size,
                   "Output WIDTHxHEIGHT: perspective default 960x540; map default the DEM grid (else resampled)");
    cmd.add_option("--exposure", a.exposure,
                   "EV100 number (e.g. 14.5 for a sunlit scene) or auto (log-average luminance to middle grey)")
        ->capture_default_str();
    cmd.add_option("--materials", a.materials,
                   "rule (height/slope: water, grass, forest, rock, snow) or a land-cover GeoTIFF of ESA WorldCover "
                   "class codes, resampled to the DEM by georeferencing")
        ->capture_default_str();
    cmd.add_option("--albedo", a.albedo,
                   "RGB orthophoto GeoTIFF (8-bit sRGB) giving the albedo of every land texel it covers");
    cmd.add_option("--directions", a.directions, "Horizon azimuths for the sky visibility (exact sweep)")
        ->capture_default_str()
        ->check(CLI::Range(4, 1024));
    cmd.add_flag("--no-curvature", a.no_curvature, "Ignore Earth curvature (default: d^2/(2 R_eff) with refraction)");
    cmd.add_option("--haze-km", a.haze_km,
                   "Perspective: aerial haze distance (transmittance exp(-d/haze)); 0 = none")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1e6));
    cmd.add_option("--exp-method", a.exp_method, "SH exponentiation (" + sh::exp_method_choices() + ")")
        ->capture_default_str();
    cmd.add_flag("--no-band-correction", a.no_band_correction,
                 "Keep the diffuse transfer as exponentiated (default: scaled per SH band so open ground gets the exact projected cosine; docs/rendering.md)");
    auto* cpu = cmd.add_flag("--cpu", a.cpu,
                             "Compute visibility, transfer and shading on the CPU (the reference path) instead of the "
                             "Vulkan device");
    cmd.add_option("--device", a.device,
                   "Vulkan device index as `terrashade devices` lists it (default: the best device; without --device "
                   "a machine with no Vulkan falls back to the CPU with a warning)")
        ->excludes(cpu);
    cmd.add_option("--sun-shadows", a.sun_shadows,
                   "Per-frame sun shadows: sweep (fast, shadow heights along the sweep lines) or exact (the "
                   "reference horizon sweep in the sun's azimuth; docs/accuracy.md)")
        ->capture_default_str()
        ->check(CLI::IsMember({"sweep", "exact"}));
    cmd.add_option("--threads", a.threads, "Worker threads (0 = one per core)")
        ->capture_default_str()
        ->check(CLI::Range(0, 256));
}

render::SceneOptions scene_options(const RenderArgs& a) {
    render::SceneOptions o;
    o.sky = light::parse_sky_options(a.sky);
    o.view = a.view == "perspective" ? render::ViewKind::perspective : render::ViewKind::map;
    if (!a.camera.empty()) {
        if (o.view != render::ViewKind::perspective) throw InputError("--camera needs --view perspective");
        o.camera = render::parse_camera(a.camera);
    }
    if (!a.size.empty()) {
        int w = 0, h = 0;
        parse_size(a.size, w, h);
        if (o.view == render::ViewKind::perspective)
            o.perspective.width = w, o.perspective.height = h;
        else
            o.map_width = w, o.map_height = h;
    }
    o.materials = a.materials;
    o.albedo = a.albedo;
    o.renderer.directions = a.directions;
    o.renderer.curvature = !a.no_curvature;
    o.renderer.exp_method = sh::parse_exp_method(a.exp_method);
    o.renderer.band_correction = !a.no_band_correction;
    o.renderer.threads = a.threads;
    o.renderer.sun_method = visibility::parse_sun_method(a.sun_shadows);
    o.perspective.haze_distance_m = a.haze_km * 1000.0;
    return o;
}

render::Exposure exposure_of(const RenderArgs& a) {
    return render::parse_exposure(a.exposure);
}

}  // namespace ts::app
