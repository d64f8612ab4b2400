#include "core/render/render_scene.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "core/light/sun_position.hpp"
#include "core/raster/image_io_plugin/float_image_io.hpp"
#include "core/raster/raster_writer.hpp"
#include "core/material/material_sources.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/util/error.hpp"

namespace ts::render {
namespace {

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// Bilinear resampling of a texel raster to w x h (texel centres aligned like GDAL's -ts).
void resample(const std::vector<glm::vec3>& src, int sw, int sh, int w, int h, std::vector<glm::vec3>& out) {
    out.resize(std::size_t(w) * h);
    for (int j = 0; j < h; ++j) {
        const double y = std::clamp((j + 0.5) * sh / h - 0.5, 0.0, double(sh - 1));
        const int y0 = std::min(int(y), sh - 1), y1 = std::min(y0 + 1, sh - 1);
        const float fy = float(y - y0);
        for (int i = 0; i < w; ++i) {
            const double x = std::clamp((i + 0.5) * sw / w - 0.5, 0.0, double(sw - 1));
            const int x0 = std::min(int(x), sw - 1), x1 = std::min(x0 + 1, sw - 1);
            const float fx = float(x - x0);
            auto at = [&](int c, int r) { return src[std::size_t(r) * sw + c]; };
            out[std::size_t(j) * w + i] =
                (at(x0, y0) * (1 - fx) + at(x1, y0) * fx) * (1 - fy) + (at(x0, y1) * (1 - fx) + at(x1, y1) * fx) * fy;
        }
    }
}

}  // namespace

Scene::Scene(const dem::Dem& dem, const SceneOptions& options) : dem_(dem), options_(options) {
    grid_ = std::make_unique<terrain::HeightGrid>(terrain::metric_view(dem_));
    NormalField normals = terrain_normals(*grid_, options_.renderer.threads);
    MaterialRaster materials;
    if (options_.materials.empty() || options_.materials == "rule") {
        materials = rule_materials(*grid_, normals, options_.rule);
    } else {
        materials = landcover_materials(*grid_, normals, read_landcover_on_grid(options_.materials, dem_.georef),
                                        options_.rule);
    }
    if (!options_.albedo.empty()) apply_albedo(materials, read_orthophoto_albedo(options_.albedo, dem_.georef));

    ViewDirections view;
    if (options_.view == ViewKind::perspective) {
        camera_ = options_.camera ? *options_.camera : default_camera(*grid_, dem_.georef);
        PerspectiveOptions po = options_.perspective;
        po.curvature = options_.renderer.curvature;
        po.threads = options_.renderer.threads;
        perspective_ = std::make_unique<PerspectiveView>(*grid_, dem_.georef, *camera_, po);
        view.per_texel = perspective_->view_directions();
    }
    renderer_ = std::make_unique<FrameRenderer>(*grid_, std::move(materials), std::move(normals), view, options_.renderer);
}

SunState Scene::sun_at(light::UtcTime time) const {
    const glm::dvec2 centre = dem_.georef.pixel_to_lonlat(dem_.width * 0.5, dem_.height * 0.5);
    double mean = 0;
    std::size_t n = 0;
    for (float z : dem_.z)
        if (!std::isnan(z)) mean += z, ++n;
    light::SunPositionInput in;
    in.time = time;
    in.observer.longitude_deg = centre.x;
    in.observer.latitude_deg = centre.y;
    in.observer.height_m = n ? mean / double(n) : 0.0;
    in.atmosphere = light::Atmosphere::standard_at(in.observer.height_m);
    const light::SunPosition p = light::sun_position(in);
    return {p.azimuth_deg, p.elevation_deg};
}

void Scene::render(const SunState& sun, LinearImage& image) {
    const glm::dvec3 s = sun_direction(sun);
    // An HDR map does not change with the sun: read it once.
    if (!sky_ || options_.sky.kind != light::SkyOptions::Kind::hdr) sky_ = light::make_sky(options_.sky, s);
    const bool resampled =
        options_.map_width > 0 && (options_.map_width != grid_->width || options_.map_height != grid_->height);
    if (!perspective_ && !resampled) {
        // A map on the DEM grid is the texels themselves: render straight into the picture
        // (a 500x500 frame's copy is 3 MB, ~0.3 ms of a ~5 ms frame).
        renderer_->render(*sky_, sun, image.rgb);
        image.width = grid_->width;
        image.height = grid_->height;
        return;
    }
    renderer_->render(*sky_, sun, texel_radiance_);
    if (perspective_) {
        sky_table_.update(*sky_);
        const light::SunDisc disc = sky_->sun();
        const double r = disc.angular_radius_rad;
        const glm::vec3 sun_radiance = disc.irradiance / float(std::numbers::pi * r * r);
        perspective_->compose(texel_radiance_.data(), sky_table_, glm::vec3(s), sun_radiance, std::cos(r), image.rgb);
        image.width = perspective_->width();
        image.height = perspective_->height();
        return;
    }
    resample(texel_radiance_, grid_->width, grid_->height, options_.map_width, options_.map_height, image.rgb);
    image.width = options_.map_width;
    image.height = options_.map_height;
}

void check_image_extension(const std::string& path) {
    const std::string ext = lower_extension(path);
    if (ext != ".png" && ext != ".tif" && ext != ".tiff" && ext != ".exr")
        throw input_error(path, "unsupported output format '" + ext + "' (use .png, .tif or .exr)");
}

double image_exposure_scale(const LinearImage& image, const Exposure& exposure) {
    return exposure_scale(exposure, exposure.automatic ? log_average_luminance(image.rgb.data(), image.rgb.size()) : 0.0);
}

double write_image(const std::string& path, const LinearImage& image, const Exposure& exposure,
                   const geo::Georef* georef) {
    check_image_extension(path);
    const std::string ext = lower_extension(path);
    if (ext == ".exr") {
        raster::write_float_image_exr(path, image.width, image.height, 3, &image.rgb[0].x, true);
        return 1.0;
    }
    const double scale = image_exposure_scale(image, exposure);
    const auto bytes = tone_map_to_srgb8(image.rgb.data(), image.rgb.size(), scale);
    const geo::Georef* geo = ext == ".png" ? nullptr : georef;
    geo::Georef scaled;
    if (geo && (geo->width() != image.width || geo->height() != image.height)) {
        geo::GeoTransform t = geo->transform();
        const double sx = double(geo->width()) / image.width, sy = double(geo->height()) / image.height;
        t.dx_col *= sx, t.dy_col *= sx, t.dx_row *= sy, t.dy_row *= sy;
        scaled = geo::Georef(image.width, image.height, t, geo->crs_ptr(), geo->pixel_is_area());
        geo = &scaled;
    }
    raster::write_u8_image(path, image.width, image.height, 3, bytes.data(), geo);
    return scale;
}

}  // namespace ts::render
