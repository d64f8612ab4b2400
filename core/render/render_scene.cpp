#include "core/render/render_scene.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "core/light/sun_position.hpp"
#include "core/raster/image_io_plugin/float_image_io.hpp"
#include "core/raster/cog_writer.hpp"
#include "core/raster/raster_writer.hpp"
#include "core/material/material_sources.hpp"
#include "core/render/open_sky_fraction.hpp"
#include "core/raster/image_writer_registry.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/terrain/outside_terrain.hpp"
#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"
#include "core/visibility/earth_curvature.hpp"

namespace ts::render {
namespace {

// The joined list of the picture extensions, for the message of an unknown one.
std::string picture_extensions_text() {
    const std::vector<std::string> exts = raster::picture_extensions();
    std::string text;
    for (std::size_t i = 0; i < exts.size(); ++i)
        text += (i == 0 ? "" : i + 1 == exts.size() ? " or " : ", ") + exts[i];
    return text;
}

}  // namespace

geo::Georef extent_georef(const ExtentRequest& e, const geo::Georef& dem_georef) {
    if (!(e.x1 > e.x0 && e.y1 > e.y0) || !std::isfinite(e.x0 + e.x1 + e.y0 + e.y1))
        throw QuantityError(Quantity::extent, "", "give XMIN,YMIN,XMAX,YMAX with XMIN < XMAX and YMIN < YMAX");
    if (e.width < 1 || e.height < 1) throw QuantityError(Quantity::extent, "", "the picture needs at least 1x1 pixels");
    const std::shared_ptr<const geo::Crs> crs = e.crs.empty() ? dem_georef.crs_ptr() : geo::Crs::from_definition(e.crs);
    if (crs->is_geographic() && (e.y0 < -90 || e.y1 > 90 || e.x0 < -360 || e.x1 > 360))
        throw QuantityError(Quantity::extent, "", "latitudes must be within -90..90 and longitudes within -360..360 "
                                                  "degrees in a geographic CRS (XMIN,YMIN,XMAX,YMAX is lon,lat,lon,lat)");
    geo::GeoTransform t;
    t.x0 = e.x0, t.dx_col = (e.x1 - e.x0) / e.width, t.dx_row = 0;
    t.y0 = e.y1, t.dy_col = 0, t.dy_row = -(e.y1 - e.y0) / e.height;
    return geo::Georef(e.width, e.height, t, crs, true);
}

Scene::Scene(const dem::Dem& dem, const SceneOptions& options)
    : dem_(dem), options_(options),
      grid_north_deg_(dem.georef.valid() ? dem.georef.grid_azimuth_of_north_deg() : 0.0) {
    // The log-SH terrain transfer has no horizons to integrate the sky over; the sky follows
    // the sky light (its aureole in the sun's beam only for SH).
    if (options_.renderer.terrain_transfer != RendererOptions::TerrainTransfer::exact)
        options_.renderer.sky_light.mode = SkyLightSettings::Mode::sh;
    options_.sky = sky_for(options_.sky, options_.renderer.sky_light);
    grid_ = std::make_unique<terrain::HeightGrid>(terrain::metric_view(dem_));
    // Meshes first: one off the DEM is an input error found before any heavy work.
    if (!options_.meshes.empty()) {
        blockers_ = place_scene_meshes(options_.meshes, *grid_, dem_.georef, options_.blocker_options, warnings_);
        options_.renderer.blockers = &blockers_;
    }
    NormalField normals = terrain_normals(*grid_, options_.renderer.threads);
    std::vector<std::uint8_t> cover;
    if (!options_.materials.empty()) cover = read_landcover_on_grid(options_.materials, dem_.georef);
    // Percent stops on this DEM's measured heights (as tiles and fly fit theirs), unless fitted.
    MaterialRaster materials =
        palette_materials(*grid_, normals, fit_colors(options_.colors, dem_), cover, options_.rule);
    if (!options_.albedo.empty()) apply_albedo(materials, read_orthophoto_albedo(options_.albedo, dem_.georef));
    // The palette's colours are designed; measured albedos (land cover, an orthophoto) span
    // 2-3x in luminance and are compressed so the relief reads first.
    const bool measured_albedo = !cover.empty() || !options_.albedo.empty();
    if (measured_albedo) compress_albedo_contrast(materials, options_.albedo_contrast);
    // Likewise an automatic relief contrast softens measured colours only, never a palette's.
    options_.relief_contrast.soften_albedo = options_.relief_contrast.soften_albedo && measured_albedo;

    // The target first: a camera below the terrain or an extent off the DEM is found before
    // the visibility is computed.
    switch (options_.view) {
        case ViewKind::map:
            target_ = std::make_unique<GridTarget>(dem_.georef, options_.map_width, options_.map_height,
                                                   terrain::unmeasured_mask(grid_->z, dem_.void_mask));
            break;
        case ViewKind::extent: {
            if (!options_.extent) throw InputError("render: an extent view needs an extent");
            auto extent = std::make_unique<ExtentTarget>(dem_, extent_georef(*options_.extent, dem_.georef),
                                                         options_.renderer.threads);
            if (extent->covered_pixels() == 0)
                throw QuantityError(Quantity::extent, "", "the extent does not overlap the DEM (check the bounds and their CRS)");
            target_ = std::move(extent);
            break;
        }
        case ViewKind::perspective: {
            PerspectiveOptions po = options_.perspective;
            po.curvature = options_.renderer.curvature;
            po.threads = options_.renderer.threads;
            auto camera = std::make_unique<CameraTarget>(
                *grid_, dem_.georef, options_.camera ? *options_.camera : default_camera(*grid_, dem_.georef), po);
            // Either picture would be one colour: the terrain's from inside it, or the sky alone.
            const PerspectiveView& view = camera->view();
            if (view.camera_below_terrain())
                throw QuantityError(Quantity::camera, "", "the camera at " + std::to_string(int(std::lround(camera->camera().height_m))) +
                                 " m is below the terrain there (" + std::to_string(int(std::lround(view.ground_height_m()))) +
                                 " m): raise its height");
            if (view.hit_count() == 0)
                throw QuantityError(Quantity::camera, "", "the camera sees no terrain (every ray misses the DEM): turn it towards "
                                 "the DEM or look further down");
            target_ = std::move(camera);
            break;
        }
    }
    if (auto* camera = dynamic_cast<CameraTarget*>(target_.get())) attach_mesh_views(camera->view());
    // A magnified map shades the sun per pixel (map_pixel_sun.hpp), unless its shading is
    // stretched (--relief-contrast), which is per texel.
    const ReliefContrast& rc = options_.relief_contrast;
    if (options_.view != ViewKind::perspective && !rc.automatic && rc.k == 1.0)
        target_->shade_sun_per_pixel(*grid_, options_.perspective.pixel_sun_shadows,
                                     visibility::curvature_factor(options_.renderer.curvature), options_.renderer.threads);
    state_ = compute_shading_state(*grid_, std::move(materials), std::move(normals), options_.renderer);
    view_ = compute_view_shading(*state_, target_->view_directions());
    renderer_ = std::make_unique<FrameRenderer>(*state_, view_);
}

Scene::~Scene() = default;

void Scene::attach_mesh_views(const PerspectiveView& view) {
    MeshLightingOptions lo;
    lo.directions = options_.renderer.directions;
    lo.curvature = options_.renderer.curvature;
    lo.terrain_log_eps = options_.renderer.visibility_log_eps;
    lo.brdf_log_eps = options_.renderer.brdf_log_eps;
    lo.terrain_shadow = options_.mesh_terrain_shadow;
    lo.self_shadow = options_.mesh_self_shadow;
    lo.threads = options_.renderer.threads;
    std::vector<const PlacedMesh*> placed;
    for (std::size_t k = 0; k < options_.meshes.size(); ++k) {
        const SceneMesh& m = options_.meshes[k];
        if (!m.triangles || m.triangles->triangle_count() == 0) continue;
        const glm::dvec2 anchor = mesh_anchor(dem_.georef, m.placement, m.name);
        const double ground = ground_height(*grid_, anchor);
        PlacedMesh pm = place_mesh(*m.triangles, placement_on_grid(dem_.georef, m.placement, anchor), anchor,
                                   std::isnan(ground) ? 0.0 : ground, m.name);
        const blockers::PlacedSpheres* spheres = k < blockers_.meshes.size() ? &blockers_.meshes[k] : nullptr;
        mesh_lighting_.push_back(
            std::make_unique<MeshLighting>(*grid_, std::move(pm), spheres, options_.blocker_options, lo));
        placed.push_back(&mesh_lighting_.back()->mesh());
    }
    if (placed.empty()) return;
    mesh_view_ = std::make_unique<MeshView>(*grid_, view, placed, options_.renderer.curvature);
    mesh_radiance_.resize(placed.size());
}

visibility::TexelRect Scene::move_mesh(std::size_t k, const mesh::Placement& placement) {
    if (k >= options_.meshes.size()) throw InputError("move_mesh: no mesh " + std::to_string(k));
    if (mesh_view_) throw InputError("a moving mesh is drawn in map and extent views only, not in perspective");
    SceneMesh& m = options_.meshes[k];
    const glm::dvec2 anchor = mesh_anchor(dem_.georef, placement, m.name);
    const double ground = ground_height(*grid_, anchor);
    if (placement.above_ground && std::isnan(ground))
        throw input_error(m.name, "an agl height over a void of the DEM: give the height above the datum");
    m.placement = placement;
    std::shared_ptr<const blockers::TriangleBvh> triangles = std::move(blockers_.meshes[k].model_triangles);
    blockers_.meshes[k] = blockers::place_spheres(m.model_spheres, placement_on_grid(dem_.georef, placement, anchor),
                                                  anchor, std::isnan(ground) ? 0.0 : ground, m.name);
    blockers_.meshes[k].model_triangles = std::move(triangles);  // one model frame for every placement
    return state_->move_mesh(k, blockers_.meshes[k]);
}

const Camera* Scene::camera() const {
    const auto* c = dynamic_cast<const CameraTarget*>(target_.get());
    return c ? &c->camera() : nullptr;
}

SunSite sun_site(const dem::Dem& dem) {
    const glm::dvec2 centre = dem.georef.pixel_to_lonlat(dem.width * 0.5, dem.height * 0.5);
    double mean = 0;
    std::size_t n = 0;
    for (float z : dem.z)
        if (!std::isnan(z)) mean += z, ++n;
    return {centre.x, centre.y, n ? mean / double(n) : 0.0};
}

SunState sun_at(const SunSite& site, light::UtcTime time) {
    light::SunPositionInput in;
    in.time = time;
    in.observer.longitude_deg = site.longitude_deg;
    in.observer.latitude_deg = site.latitude_deg;
    in.observer.height_m = site.height_m;
    in.atmosphere = light::Atmosphere::standard_at(in.observer.height_m);
    const light::SunPosition p = light::sun_position(in);
    return {p.azimuth_deg, p.elevation_deg};
}

SunState sun_at_dem_centre(const dem::Dem& dem, light::UtcTime time) { return sun_at(sun_site(dem), time); }

SunState Scene::sun_at(light::UtcTime time) const { return on_grid(sun_at_dem_centre(dem_, time)); }

SunState Scene::on_grid(const SunState& true_sun) const { return sun_on_grid(true_sun, grid_north_deg_); }

std::vector<float> Scene::open_sky_fraction() { return render::open_sky_fraction(*renderer_); }

void Scene::render(const SunState& sun, LinearImage& image) {
    const glm::dvec3 s = sun_direction(sun);
    // An HDR map does not change with the sun: read it once.
    if (!sky_ || options_.sky.kind != light::SkyOptions::Kind::hdr) sky_ = light::make_sky(options_.sky, s);
    const bool map = options_.view != ViewKind::perspective;
    auto stretch = [&](std::vector<glm::vec3>& radiance) {
        const ReliefContrast& rc = options_.relief_contrast;
        last_relief_ = map && (rc.automatic || rc.k != 1.0) ? apply_relief_contrast(radiance, state_->materials(), rc)
                                                            : ReliefContrastApplied{};
    };
    if (target_->is_texel_grid()) {
        // A map on the DEM grid is the texels themselves: render straight into the picture
        // (a 500x500 frame's copy is 3 MB, ~0.3 ms of a ~5 ms frame).
        renderer_->render(*sky_, sun, image.rgb);
        stretch(image.rgb);
        image.width = grid_->width;
        image.height = grid_->height;
        image.alpha.clear();
        static_cast<const GridTarget&>(*target_).mark_outside(image);
        return;
    }
    renderer_->render(*sky_, sun, texel_radiance_);
    stretch(texel_radiance_);
    if (map && !target_->shades_sun_per_pixel()) {
        target_->compose(texel_radiance_, nullptr, *sky_, image);
    } else {
        // A camera, or a magnified map, shades the sun's diffuse term with each pixel's normal
        // (pixel_sun_shading.hpp).
        const MaterialRaster& m = state_->materials();
        const NormalField& nf = state_->normals();
        TexelSunTerm term;
        term.albedo_r = m.albedo_r.data(), term.albedo_g = m.albedo_g.data(), term.albedo_b = m.albedo_b.data();
        term.water = m.water.empty() ? nullptr : m.water.data();
        term.visibility = renderer_->sun_visibility().data();
        term.nx = nf.x.data(), term.ny = nf.y.data(), term.nz = nf.z.data();
        term.direction = glm::vec3(sun_direction(sun));
        // As the frame's: no sun term while the disc is below the horizon or dark.
        const light::SunDisc disc = sky_->sun();
        const bool sun_up = sun.elevation_deg > -disc.angular_radius_rad * 180.0 / std::numbers::pi;
        term.irradiance_over_pi = sun_up ? disc.irradiance * float(1.0 / std::numbers::pi) : glm::vec3(0.0f);
        // Per-pixel shadows: the terrain's by rays, the meshes' at each pixel. (A scene's state
        // has no outer shadow, the terrain beyond a window, which pixel rays could not see.)
        if (!state_->has_outer_sun_shadow()) {
            term.terrain_visibility = renderer_->terrain_sun_visibility().data();
            if (!state_->blockers().empty()) {
                if (!pixel_blockers_)
                    pixel_blockers_ = std::make_unique<PixelSunBlockers>(
                        *grid_, state_->blockers(), visibility::curvature_factor(options_.renderer.curvature));
                pixel_blockers_->set_sun(sun_direction(sun));
                term.blockers = pixel_blockers_.get();
            }
        }
        target_->compose(texel_radiance_, &term, *sky_, image);
    }
    if (mesh_view_) {
        const auto* camera = dynamic_cast<const CameraTarget*>(target_.get());
        const light::SkySh sky_sh = light::project_sky_sh(*sky_);
        const light::SunDisc disc = sky_->sun();
        const glm::vec3 e = disc.irradiance;
        const bool sun_up = (e.x > 0 || e.y > 0 || e.z > 0) &&
                            sun.elevation_deg > -disc.angular_radius_rad * 180.0 / std::numbers::pi;
        for (std::size_t m = 0; m < mesh_lighting_.size(); ++m)
            mesh_lighting_[m]->radiance(sky_sh, disc, sun_up, mesh_radiance_[m]);
        mesh_view_->compose(mesh_radiance_, camera->sky_table(), image.rgb);
    }
}

void check_image_extension(const std::string& path) {
    const raster::ImageFormat* f = raster::find_image_format(path);
    if (!f || f->tile_set)
        throw input_error(path, "unsupported output format '" + std::filesystem::path(path).extension().string() +
                                    "' (use " + picture_extensions_text() + ")");
}

double image_exposure_scale(const LinearImage& image, const Exposure& exposure) {
    if (!exposure.automatic) return exposure_scale(exposure, 0.0);
    if (image.alpha.empty()) return exposure_scale(exposure, log_average_luminance(image.rgb.data(), image.rgb.size()));
    std::vector<glm::vec3> covered;
    for (std::size_t k = 0; k < image.rgb.size(); ++k)
        if (image.alpha[k]) covered.push_back(image.rgb[k]);
    return exposure_scale(exposure, log_average_luminance(covered.data(), covered.size()));
}

double write_image(const std::string& path, const LinearImage& image, const Exposure& exposure,
                   const geo::Georef* georef) {
    check_image_extension(path);
    const raster::ImageFormat& format = *raster::find_image_format(path);
    const bool rgba = !image.alpha.empty();
    if (format.writer == raster::ImageWriter::exr) {
        if (!rgba) {
            raster::write_float_image_exr(path, image.width, image.height, 3, &image.rgb[0].x, true);
        } else {
            std::vector<float> px(image.rgb.size() * 4);
            for (std::size_t k = 0; k < image.rgb.size(); ++k) {
                px[4 * k] = image.rgb[k].x, px[4 * k + 1] = image.rgb[k].y, px[4 * k + 2] = image.rgb[k].z;
                px[4 * k + 3] = image.alpha[k] / 255.0f;
            }
            raster::write_float_image_exr(path, image.width, image.height, 4, px.data(), true);
        }
        return 1.0;
    }
    const double scale = image_exposure_scale(image, exposure);
    std::vector<std::uint8_t> bytes =
        tone_map_to_srgb8(image.rgb.data(), image.rgb.size(), scale, {0, 0, 0}, exposure.dither ? image.width : 0);
    if (rgba) {
        std::vector<std::uint8_t> with_alpha(image.rgb.size() * 4);
        for (std::size_t k = 0; k < image.rgb.size(); ++k) {
            for (int c = 0; c < 3; ++c) with_alpha[4 * k + c] = image.alpha[k] ? bytes[3 * k + c] : 0;
            with_alpha[4 * k + 3] = image.alpha[k];
        }
        bytes = std::move(with_alpha);
    }
    const geo::Georef* geo = format.georeferenced ? georef : nullptr;
    geo::Georef scaled;
    if (geo && (geo->width() != image.width || geo->height() != image.height)) {
        geo::GeoTransform t = geo->transform();
        const double sx = double(geo->width()) / image.width, sy = double(geo->height()) / image.height;
        t.dx_col *= sx, t.dy_col *= sx, t.dx_row *= sy, t.dy_row *= sy;
        scaled = geo::Georef(image.width, image.height, t, geo->crs_ptr(), geo->pixel_is_area());
        geo = &scaled;
    }
    // A georeferenced map as a Cloud-Optimized GeoTIFF (tiled, with overviews): GIS and web
    // clients read any window or zoom of it without the whole file.
    if (geo && geo->valid())
        raster::write_cog_u8(path, image.width, image.height, rgba ? 4 : 3, bytes.data(), *geo);
    else
        raster::write_u8_image(path, image.width, image.height, rgba ? 4 : 3, bytes.data(), geo);
    return scale;
}

}  // namespace ts::render
