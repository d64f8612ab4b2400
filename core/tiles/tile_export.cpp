#include "core/tiles/tile_export.hpp"

#include "core/tiles/tile_insolation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <mutex>
#include <map>
#include <memory>
#include <string_view>
#include <tuple>
#include <utility>

#include "core/raster/png_writer.hpp"
#include "core/render/render_scene.hpp"
#include "core/tiles/block_shading.hpp"
#include "core/tiles/legible_relief.hpp"
#include "core/tiles/lightable_sky.hpp"
#include "core/tiles/shade_source.hpp"
#include "core/tiles/tile_pixels.hpp"
#include "core/tiles/tile_renderer.hpp"
#include "core/tiles/tile_shard.hpp"
#include "core/tiles/zoom_exaggeration.hpp"
#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/progress_bar.hpp"
#include "core/util/stopwatch.hpp"

namespace ts::tiles {
namespace {

// Sources keep at least this many texels per side: coarser levels than that show nothing.
constexpr int kMinLevelTexels = 32;

std::string number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// The sky as the job's description holds it: kind and turbidity as always, then only what
// differs from the defaults, so that older jobs describe themselves as before.
std::string sky_fingerprint(const light::SkyOptions& sky) {
    const light::SkyOptions defaults;
    std::string out = std::to_string(int(sky.kind)) + "_" + number(sky.turbidity);
    if (sky.ground_albedo != defaults.ground_albedo) out += "_albedo" + number(sky.ground_albedo);
    if (sky.kind == light::SkyOptions::Kind::physical && !sky.multiple_scattering) out += "_single";
    if (sky.kind == light::SkyOptions::Kind::physical) out += "_aureole" + number(sky.aureole_deg);
    if (sky.kind == light::SkyOptions::Kind::overcast && sky.overcast_brightness != defaults.overcast_brightness)
        out += "_brightness" + number(sky.overcast_brightness);
    if (sky.kind == light::SkyOptions::Kind::hdr) {
        std::string path = sky.hdr_path;
        std::replace_if(path.begin(), path.end(), [](char c) { return c == '"' || c == '\\' || c < ' '; }, '_');
        out += "_" + path + "_" + number(sky.hdr_rotation_deg) + "_" + number(sky.hdr_scale);
    }
    return out;
}

}  // namespace

void check_tile_job(const TileJob& job) {
    if (job.z0 < 0 || job.z1 > kMaxZoom || job.z0 > kMaxZoom || job.z1 < 0)
        throw QuantityError(Quantity::zoom, "", "zooms are 0.." + std::to_string(kMaxZoom));
    if (job.z1 < job.z0) throw QuantityError(Quantity::zoom, "Z0-Z1", "Z1 must not be below Z0");
    if (job.tile_size != 256 && job.tile_size != 512) throw QuantityError(Quantity::tile_size, "", "256 or 512");
    if (job.z1 + tile_size_shift(job.tile_size) > kMaxZoom + 1)
        throw QuantityError(Quantity::zoom, "", "512-px tiles go to zoom " + std::to_string(kMaxZoom - 1));
    const TileShading& s = job.shading;
    if (!(s.z_factor > 0) || !std::isfinite(s.z_factor)) throw QuantityError(Quantity::z_factor, "", "must be a finite number > 0");
    if (s.exaggeration && (!(*s.exaggeration > 0) || !std::isfinite(*s.exaggeration)))
        throw QuantityError(Quantity::exaggeration, "", "must be a finite number > 0");
    if (!(s.sun_elevation_deg >= -90 && s.sun_elevation_deg <= 90)) throw QuantityError(Quantity::sun_elevation, "", "-90..90 degrees");
    if (!(s.sun_azimuth_deg >= 0 && s.sun_azimuth_deg <= 360)) throw QuantityError(Quantity::sun_azimuth, "", "0..360 degrees");
    if (s.directions < 4) throw QuantityError(Quantity::directions, "", "at least 4");
    if (s.block_texels != 0 && s.block_texels < 64) throw QuantityError(Quantity::block_texels, "", "0 (never) or at least 64");
    if (s.block_halo_texels < 1) throw QuantityError(Quantity::block_halo, "", "at least 1 texel");
    if (job.level_bias < -4 || job.level_bias > 4) throw QuantityError(Quantity::level_bias, "", "-4..4 levels");
    if (!(s.relief_contrast >= 0.25 && s.relief_contrast <= 4))
        throw QuantityError(Quantity::relief_contrast, "", "a number from 0.25 to 4 (1 = the physical shading)");
    if (s.style->data_tile() && (s.light_directions < 8 || s.light_directions > 1024 || s.light_directions % 4))
        throw QuantityError(Quantity::light_directions, "", "a multiple of 4 from 8 to 1024");
    if (s.style->data_tile() && (s.light_components < 1 || s.light_components > 9))
        throw QuantityError(Quantity::light_components, "", "1 to 9");
    if (s.relief_contrast != 1.0 && !s.style->takes_relief_contrast())
        throw QuantityError(Quantity::relief_contrast, "", "only the relief style has it");
}

std::vector<TileId> plan_tiles(const dem::Dem& dem, const TileJob& job) {
    return shard_tiles(tiles_covering(terrain_footprint(dem), job.z0, job.z1), job.shard);
}

std::string describe_job(const TileJob& job) {
    const TileShading& s = job.shading;
    std::string by_zoom;  // only with --max-error, so that older jobs describe themselves as before
    for (const auto& [z, d] : job.directions_by_zoom)
        by_zoom += (by_zoom.empty() ? ",\"directions_by_zoom\":{\"" : ",\"") + std::to_string(z) + "\":" + std::to_string(d);
    if (!by_zoom.empty()) by_zoom += "}";
    // Likewise only when not the default.
    const std::string contrast = s.relief_contrast != 1.0 ? ",\"relief_contrast\":" + number(s.relief_contrast) : "";
    const std::string bias = job.level_bias != 0 ? ",\"level_bias\":" + std::to_string(job.level_bias) : "";
    const std::string max_error = s.max_error > 0 ? ",\"block_max_error\":" + number(s.max_error) : "";
    const std::string dem = job.dem.empty() ? "" : ",\"dem\":\"" + job.dem + "\"";
    std::string colors;  // only for a style that colours land
    if (s.style->colours_land()) {
        colors = ",\"colors\":\"" + s.colors.palette.describe() + "\"";
        if (s.colors.snow_line_m) colors += ",\"snow_line\":" + number(*s.colors.snow_line_m);
    }
    const std::string insolation = s.insolation ? ",\"insolation\":\"" + s.insolation->describe + "\"" : "";
    const std::string light = s.style->data_tile() ? ",\"light\":\"" + std::to_string(s.light_directions) + "_" +
                                                         std::to_string(s.light_components) + "\""
                                                   : "";
    const bool lit = s.style->takes_relief_contrast() || s.style->colours_land() || s.style->data_tile();
    const std::string bounce = lit ? ",\"bounce\":\"" + std::to_string(s.bounce.bounces) + "_" +
                                         std::to_string(s.bounce.gather.directions) + "_" +
                                         number(s.bounce.gather.radius_texels) + "_" +
                                         number(s.bounce.gather.growth) + "\""
                                   : "";
    // Only when the sky's light is integrated over the horizons (tiles made before were all SH).
    const bool rendered = s.style->takes_relief_contrast() || s.style->colours_land();
    const std::string sky_light =
        rendered && s.sky_light.mode == render::SkyLightSettings::Mode::horizons
            ? ",\"sky_light\":\"horizons_" + std::to_string(s.sky_light.sectors) + "_" +
                  std::to_string(s.sky_light.elevation_steps) + "\""
            : "";
    // Only when the bounce's sun part is gathered per frame (tiles made before took it through SH).
    const std::string bounce_sun =
        rendered && s.bounce.bounces > 0 && s.bounce.sun == render::BounceSettings::SunPart::gather
            ? ",\"bounce_sun\":\"gather\""
            : "";
    // The Horn styles' heights follow --resampling (before, they were bilinear whatever it said:
    // a set made then is another job).
    const std::string horn_heights =
        !s.style->uses_visibility() && s.resampling == Resampling::cubic ? ",\"heights\":\"cubic\"" : "";
    // Everything that changes a tile's bytes (not the zoom range: a resumed run may extend it).
    return std::string("{\"style\":\"") + std::string(s.style->name()) + "\",\"tile_size\":" +
           std::to_string(job.tile_size) + ",\"sun_azimuth\":" + number(s.sun_azimuth_deg) +
           ",\"sun_elevation\":" + number(s.sun_elevation_deg) + ",\"z_factor\":" + number(s.z_factor) +
           ",\"exaggeration\":" + (s.exaggeration ? number(*s.exaggeration) : std::string("\"auto-native\"")) +
           ",\"directions\":" + std::to_string(s.directions) + ",\"block\":" + std::to_string(s.block_texels) +
           ",\"halo\":" + std::to_string(s.block_halo_texels) + ",\"far_field\":\"" +
           std::string(far_field_name(s.far_field)) + "\",\"resampling\":\"" + std::string(resampling_name(s.resampling)) +
           "\"" + ",\"sky\":\"" + sky_fingerprint(s.sky) + "\"" + contrast + bias +
           by_zoom + max_error + dem + colors + insolation + light + bounce + sky_light + bounce_sun + horn_heights +
           "}\n";
}

LightableEncoding lightable_encoding(const dem::Dem& dem, const TileShading& s) {
    const double latitude = dem.georef.pixel_to_lonlat(dem.width * 0.5, dem.height * 0.5).y;
    LightableEncoding e;
    e.directions = s.light_directions;
    e.components = s.light_components;
    e.bands = sun_bands(latitude, s.light_directions, dem.georef.grid_azimuth_of_north_deg());
    return e;
}

std::string lightable_json(const dem::Dem& dem, const TileShading& s) {
    const render::SunSite site = render::sun_site(dem);
    return lightable_json(s,
                          {site.longitude_deg, site.latitude_deg, site.height_m, dem.georef.grid_azimuth_of_north_deg()},
                          flat_diffuse_transfer(s),
                          lightable_encoding(dem, s).bands);
}

std::string dem_identity(const dem::Dem& dem) {
    const LonLatBox b = dem_footprint(dem.georef);
    // The heights themselves too: a DEM edited in place (same size, same place) is another job,
    // whose tiles must not be resumed from the old ones. (~0.1 s for 10^8 heights.)
    const std::size_t heights = std::hash<std::string_view>{}(
        std::string_view(reinterpret_cast<const char*>(dem.z.data()), dem.z.size() * sizeof(float)));
    char text[192];
    std::snprintf(text, sizeof text, "%dx%d %.9f,%.9f,%.9f,%.9f heights %016zx", dem.width, dem.height, b.west,
                  b.south, b.east, b.north, heights);
    return text;
}

TileShading shading_of_zoom(const TileJob& job, int z) {
    TileShading s = job.shading;
    if (const auto it = job.directions_by_zoom.find(z); it != job.directions_by_zoom.end()) s.directions = it->second;
    return s;
}

ZoomShading zoom_shading(const dem::Dem& dem, const TileJob& job, int pixel_zoom) {
    const glm::dvec2 cell = dem.georef.cell_size_m();
    const double texel_m = std::sqrt(cell.x * cell.y);
    const glm::dvec2 centre = dem.georef.pixel_to_lonlat(dem.width * 0.5, dem.height * 0.5);
    const double centre_cos = std::cos(centre.y * 3.14159265358979323846 / 180.0);
    int max_level = 0;
    while (std::min(dem.width, dem.height) >> (max_level + 1) >= kMinLevelTexels) ++max_level;
    ZoomShading z;
    const int matched_level = pyramid_level_for(texel_m, pixel_size_m(pixel_zoom) * centre_cos, max_level);
    z.level = std::clamp(matched_level + job.level_bias, 0, max_level);
    // Zooms finer than the DEM's own (shaded from level 0 however far they zoom in) magnify its
    // native zoom's tiles and show no new relief: they keep that zoom's exaggeration, so they
    // share its source (one visibility pass) and do not fade as the map zooms in. Being
    // over-zoomed only grows with the zoom, so walking down from a zoom that is finds the
    // coarsest one still so, and from one that is not moves nowhere.
    auto over_zoomed = [&](int pz) { return pyramid_level_for(texel_m, pixel_size_m(pz) * centre_cos, 64) == 0; };
    int native_zoom = pixel_zoom;
    while (native_zoom > 0 && over_zoomed(native_zoom - 1)) --native_zoom;
    if (job.shading.exaggeration) {
        z.vertical_scale = job.shading.z_factor * *job.shading.exaggeration;
        return z;
    }
    // Raised where the matched level's relief is too gentle to read (legible_relief.hpp); from
    // the level the zoom matches, so --level-bias leaves it as it is.
    z.rule_exaggeration = zoom_exaggeration(native_zoom);
    const double rule = z.rule_exaggeration;
    z.vertical_scale = job.shading.z_factor *
                       (rule > 1 ? legible_exaggeration(rule, steep_slope(dem, std::max(0, matched_level))) : rule);
    return z;
}

TileHeights tile_heights(const dem::Dem& dem, const TileJob& job, const TileId& t) {
    const TileFrame f = tile_frame(t, job.tile_size);
    const ZoomShading zs = zoom_shading(dem, job, f.pixel_zoom);
    TileShading heights_only = job.shading;
    heights_only.style = find_tile_style("hillshade");  // a style shaded from heights
    const ShadeSource source = make_shade_source(dem, heights_only, zs.level, zs.vertical_scale);
    TileScratch scratch;
    sample_tile_heights(TilePixelMap(dem), source, f, scratch, job.shading.resampling);
    const double res = pixel_size_m(f.pixel_zoom);
    geo::GeoTransform g;
    g.x0 = pixel_centre_m(f.col0 - 1, f.pixel_zoom) - 0.5 * res, g.dx_col = res, g.dx_row = 0;
    g.y0 = -(pixel_centre_m(f.row0 - 1, f.pixel_zoom) - 0.5 * res), g.dy_col = 0, g.dy_row = -res;
    return {std::move(scratch.values), geo::Georef(f.size + 2, f.size + 2, g, geo::Crs::from_epsg(3857), true)};
}

TileExportStats export_tiles(const dem::Dem& dem, const TileJob& job, TileSink& sink, ProgressBar* progress) {
    check_tile_job(job);
    TileExportStats stats;
    const std::vector<TileId> plan = plan_tiles(dem, job);
    stats.planned = plan.size();
    const TilePixelMap map(dem);
    const int workers = thread_count(job.shading.threads);
    // Sources by (level, vertical scale, directions): zooms that share all three share the source.
    std::map<std::tuple<int, double, int>, std::shared_ptr<const ShadeSource>> sources;
    std::vector<TileScratch> scratch(static_cast<std::size_t>(workers));
    std::vector<TileImage> images(static_cast<std::size_t>(workers));
    std::vector<std::size_t> written(static_cast<std::size_t>(workers), 0), empty(static_cast<std::size_t>(workers), 0);
    const raster::PngEncoding encoding;
    // A data style's encoding: the light directions the sun can reach at the DEM's centre.
    std::unique_ptr<LightableEncoding> lightable;
    if (job.shading.style->data_tile()) lightable = std::make_unique<LightableEncoding>(lightable_encoding(dem, job.shading));

    for (int z = job.z0; z <= job.z1; ++z) {
        std::vector<TileId> pending;
        for (const TileId& t : plan)
            if (t.z == z) {
                if (sink.has(t)) {
                    ++stats.resumed;
                    if (progress) progress->advance();
                } else {
                    pending.push_back(t);
                }
            }
        if (pending.empty()) continue;
        const int pixel_zoom = z + tile_size_shift(job.tile_size);
        const ZoomShading zs = zoom_shading(dem, job, pixel_zoom);
        const TileShading shading = shading_of_zoom(job, z);
        const auto key = std::make_tuple(zs.level, zs.vertical_scale, shading.directions);
        if (!sources.count(key)) {
            // Only the next zooms can share a source: drop the others (memory).
            sources.clear();
            const Stopwatch watch;
            sources[key] = std::make_shared<const ShadeSource>(make_shade_source(dem, shading, zs.level, zs.vertical_scale));
            stats.source_seconds += watch.seconds();
            for (const auto& [d, n] : sources[key]->blocks_by_directions) stats.blocks_by_directions[zs.level][d] += n;
        }
        const ShadeSource& source = *sources[key];
        const Stopwatch watch;
        // A worker's error (a full disk) stops the others and is rethrown here.
        std::exception_ptr failure;
        std::mutex failure_mutex;
        parallel_for(int(pending.size()), workers, [&](int item, int worker) {
            {
                const std::lock_guard lock(failure_mutex);
                if (failure) return;
            }
            try {
            const TileId& t = pending[std::size_t(item)];
            TileImage& image = images[std::size_t(worker)];
            render_tile(map, source, job.shading, tile_frame(t, job.tile_size), scratch[std::size_t(worker)], image,
                        lightable.get());
            if (image.covered == 0) {
                ++empty[std::size_t(worker)];
            } else if (!image.encoded.empty()) {
                sink.put(t, std::move(image.encoded));
                ++written[std::size_t(worker)];
            } else {
                sink.put(t, raster::encode_png(image.size, image.size, image.channels, image.pixels.data(), encoding));
                ++written[std::size_t(worker)];
            }
            if (progress) progress->advance();
            } catch (...) {
                const std::lock_guard lock(failure_mutex);
                if (!failure) failure = std::current_exception();
            }
        });
        if (failure) std::rethrow_exception(failure);
        stats.tile_seconds += watch.seconds();
    }
    sink.finish();
    for (int w = 0; w < workers; ++w) stats.written += written[std::size_t(w)], stats.empty += empty[std::size_t(w)];
    return stats;
}

}  // namespace ts::tiles
