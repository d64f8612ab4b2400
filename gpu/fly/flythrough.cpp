#include "gpu/fly/flythrough.hpp"

#include <algorithm>
#include <cmath>

#include <glm/packing.hpp>

#include "core/blockers/placed_spheres.hpp"
#include "core/blockers/projected_cover_share.hpp"
#include "core/blockers/self_sky_shadow.hpp"
#include "core/blockers/sphere_hierarchy.hpp"
#include "core/blockers/sphere_occlusion_shared.hpp"
#include "core/light/sky.hpp"
#include "core/mesh/placement.hpp"
#include "core/fly/radiance_pack.hpp"
#include "core/render/texel_sun_split.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/render/tone_map.hpp"
#include "core/visibility/far_field_horizons.hpp"
#include "core/util/angles.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/progress_bar.hpp"
#include "core/util/stopwatch.hpp"

namespace ts::gpu {
namespace {

std::unique_ptr<render::Scene> make_scene(const dem::Dem& dem, const FlySettings& s) {
    render::SceneOptions options;
    options.view = render::ViewKind::map;
    options.sky = light::parse_sky_options(s.sky);
    options.colors = render::fit_colors(s.colors, dem);
    options.renderer.directions = s.directions;
    options.renderer.bounce = s.bounce;
    options.renderer.sky_light = s.sky_light;
    options.renderer.keep_sun_horizon = s.pixel_sun_shadows;  // the fragments place shadow edges inside texels
    ProgressBar bar("visibility", std::uint64_t(dem.width) * std::uint64_t(dem.height) * std::uint64_t(s.directions),
                    "rays");
    options.renderer.progress = &bar;
    auto scene = std::make_unique<render::Scene>(dem, options);
    bar.finish();
    return scene;
}

// The overview's level for a budget: the finest whose shading state takes at most a quarter of
// it (the rest is for the detail tiles).
int overview_level_for(const dem::DemLayout& l, const FlySettings& s) {
    if (s.overview_level > 0) return s.overview_level;
    for (int level = 1; level < 12; ++level) {
        const std::int64_t w = (l.width - 1) / (1 << level) + 1, h = (l.height - 1) / (1 << level) + 1;
        if (whole_fly_bytes(w * h) <= s.memory_budget_bytes / 4) return level;
    }
    return 12;
}

}  // namespace

std::size_t whole_fly_bytes(std::int64_t texels) { return std::size_t(std::max<std::int64_t>(texels, 0)) * 280; }

Flythrough::Flythrough(const dem::Dem& dem, const FlySettings& settings, Context& context)
    : settings_(settings), georef0_(&dem.georef), scene_(make_scene(dem, settings)), frame_(scene_->grid()),
      context_(context) {
    tree_ = std::make_unique<fly::CdlodTree>(scene_->grid(), frame_, settings_.lod);
    for (float z : scene_->grid().z) z_top_ = std::max(z_top_, double(z));
    init_renderer();
}

Flythrough::Flythrough(const dem::DemSource& source, const FlySettings& settings, Context& context)
    : settings_(settings), georef0_(&source.layout().georef), source_(&source), context_(context) {
    fly::TerrainOverviewOptions oo;
    oo.level = overview_level_for(source.layout(), settings_);
    oo.lod = settings_.lod;
    oo.threads = 0;
    visibility::FarFieldOptions fo;
    fo.start_texels = settings_.detail_halo;
    // The far field's coarse copy: the level its nearest samples would read, or coarser, so its
    // pyramid (~12 bytes a texel of the copy) stays within an eighth of the budget.
    oo.far_shift = visibility::FarField::coarse_shift_for(fo, source.layout().width, source.layout().height);
    const double texels = double(source.layout().width) * double(source.layout().height);
    while (oo.far_shift < 12 && 12.0 * texels / std::exp2(2.0 * oo.far_shift) > double(settings_.memory_budget_bytes) / 8.0)
        ++oo.far_shift;
    {
        ProgressBar bar("overview", std::uint64_t(source.layout().width) * std::uint64_t(source.layout().height), "texels");
        overview_ = std::make_unique<fly::TerrainOverview>(fly::build_terrain_overview(source, oo, &bar));
    }
    z_top_ = overview_->z_top;
    terrain::HeightGrid far_grid;
    far_grid.width = overview_->far_width, far_grid.height = overview_->far_height;
    far_grid.z = overview_->far_mean;
    far_grid.dx_m = overview_->far_dx_m, far_grid.dy_m = overview_->far_dy_m;
    far_ = std::make_unique<visibility::FarField>(far_grid, overview_->far_shift, overview_->width, overview_->height,
                                                  overview_->dx0_m, overview_->dy0_m, float(overview_->z_top), fo);
    scene_ = make_scene(overview_->points, settings_);
    grid0_.width = overview_->width, grid0_.height = overview_->height;
    grid0_.dx_m = overview_->dx0_m, grid0_.dy_m = overview_->dy0_m;
    frame_ = fly::GridFrame(grid0_);
    fly::DetailCacheOptions co;
    co.budget_bytes = settings_.memory_budget_bytes - std::min(settings_.memory_budget_bytes,
                                                               whole_fly_bytes(std::int64_t(overview_->points.z.size())) + far_->bytes());
    co.shading.halo = settings_.detail_halo;
    co.shading.directions = settings_.directions;
    co.shading.bounce = settings_.bounce;
    co.shading.sky_light = settings_.sky_light;
    co.shading.sun_horizon = settings_.pixel_sun_shadows;
    co.shading.sky = settings_.sky;
    co.shading.colors = settings_.colors;  // the cache fits it on the overview, as make_scene does
    cache_ = std::make_unique<fly::DetailTileCache>(source, *overview_, *far_, frame_, settings_.lod.patch_quads, co);
    tree_ = std::make_unique<fly::CdlodTree>(overview_->cdlod, frame_, settings_.lod, cache_.get());
    init_renderer();
}

void Flythrough::init_renderer() {
    std::vector<float> rows(std::size_t(frame_.height()) * 2);
    for (int r = 0; r < frame_.height(); ++r) {
        rows[std::size_t(2 * r)] = float(frame_.row_dx_m()[std::size_t(r)]);
        rows[std::size_t(2 * r + 1)] = float(frame_.row_north_m()[std::size_t(r)]);
    }
    FlyTerrain terrain;
    terrain.width = frame_.width();
    terrain.height = frame_.height();
    terrain.rows = rows;
    terrain.heights = scene_->grid().z;
    terrain.overview_width = scene_->grid().width;
    terrain.overview_height = scene_->grid().height;
    terrain.overview_scale = overview_ ? 1 << overview_->level : 1;
    terrain.patch_quads = settings_.lod.patch_quads;
    if (cache_) {
        terrain.atlas_slots = cache_->slots();
        terrain.atlas_samples = cache_->layout().tile_texels + 1;
        terrain.detail_levels = tree_->stored_level();
    }
    renderer_ = std::make_unique<FlyRenderer>(context_, terrain, settings_.width, settings_.height);
    render::PointTerrainLightOptions light_options;
    light_options.directions = settings_.directions;
    aircraft_lighting_ = std::make_unique<render::PointTerrainLighting>(scene_->grid(), light_options);
}

Flythrough::~Flythrough() = default;

double Flythrough::set_time(light::UtcTime time) {
    if (lit_ && time == time_) return 0.0;
    const Stopwatch watch;
    time_ = time;
    lit_ = true;
    sun_ = scene_->sun_at(time);
    if (open_sky_.empty()) open_sky_ = scene_->open_sky_fraction();  // before the frame: it renders one
    scene_->render(sun_, radiance_);
    const light::Sky& sky = *scene_->last_sky();
    const std::size_t texels = radiance_.rgb.size();
    packed_.resize(2 * texels);
    packed_sun_.resize(4 * texels);
    // The sun's diffuse term apart, for the fragments to shade between texels (and what an
    // aircraft's shadow takes away), with the texel's open-sky fraction, which scales what the
    // aircraft takes of the rest.
    const render::TexelSunSplitter split(*scene_, sun_, sky);
    for (std::size_t t = 0; t < texels; ++t) {
        const render::TexelSunLight l = split(t, radiance_.rgb[t]);
        fly::pack_radiance(l.rest, 0.0f, &packed_[2 * t]);
        fly::pack_sun_light(l.sun_albedo, open_sky_[t], l.normal, l.horizon_above_sun, &packed_sun_[4 * t]);
    }
    renderer_->set_radiance(packed_);
    renderer_->set_sun_radiance(packed_sun_);
    if (cache_) {
        cache_->set_sun(sun_);
        upload_tiles();
    }
    sky_table_.update(sky);
    sky_sh_ = light::project_sky_sh(sky);
    aircraft_light_ = {sky_sh_, 1.0f};
    aircraft_lit_ = false;
    renderer_->set_sky(fly::sky_buffer(sky_table_));
    const light::SunDisc disc = sky.sun();
    sun_dir_ = glm::vec3(disc.direction);
    sun_radiance_ = fly::sun_disc_radiance(disc);
    sun_cos_radius_ = std::cos(disc.angular_radius_rad);
    sun_radius_rad_ = disc.angular_radius_rad;
    exposure_ = render::image_exposure_scale(radiance_, render::Exposure{});
    return watch.milliseconds();
}

void Flythrough::upload_tiles() {
    for (const fly::DetailSlotData& d : cache_->take_uploads())
        renderer_->set_tile(d.slot, d.samples_x, d.samples_y, *d.heights, d.radiance, d.sun);
}

void Flythrough::assign_tile_slots() {
    const fly::DetailTileLayout& l = cache_->layout();
    for (fly::CdlodPatch& p : selection_.patches) {
        if (p.level >= l.levels_below) continue;
        const int size = settings_.lod.patch_quads << p.level;
        const int ix = int(p.col0) / size, iy = int(p.row0) / size;
        p.slot = cache_->slot_of_node(p.level, ix, iy);
        const fly::DetailTileKey key = fly::tile_of_node(l, p.level, ix, iy);
        p.tile_col0 = float(key.tx * l.tile_texels), p.tile_row0 = float(key.ty * l.tile_texels);
    }
}

fly::CameraPose Flythrough::pose_of(const fly::FlightPose& p) const {
    const glm::dvec2 px = georef0_->lonlat_to_pixel({p.lon_deg, p.lat_deg});
    const glm::dvec2 m = frame_.to_metric(px.x - 0.5, px.y - 0.5);
    fly::CameraPose c;
    c.eye = {m.x, m.y, p.height_m};
    c.heading_deg = p.heading_deg;
    c.pitch_deg = p.pitch_deg;
    c.roll_deg = p.roll_deg;
    return c;
}

glm::dvec2 Flythrough::lonlat_of(const glm::dvec3& eye) const {
    const glm::dvec2 g = frame_.to_grid(eye.x, eye.y);
    return georef0_->pixel_to_lonlat(g.x + 0.5, g.y + 0.5);
}

fly::FlightPose Flythrough::flight_pose_of(const fly::CameraPose& c, double t_s) const {
    const glm::dvec2 ll = lonlat_of(c.eye);
    return {t_s, ll.x, ll.y, c.eye.z, c.heading_deg, c.pitch_deg, c.roll_deg};
}

double Flythrough::ground_height_m(const glm::dvec3& eye) const {
    const glm::dvec2 g0 = frame_.to_grid(eye.x, eye.y);
    const double x0 = std::clamp(g0.x, 0.0, double(frame_.width() - 1)), y0 = std::clamp(g0.y, 0.0, double(frame_.height() - 1));
    auto bilinear = [](auto at, int w, int h, double x, double y) {
        const int c0 = std::min(int(x), w - 2), r0 = std::min(int(y), h - 2);
        const double fc = x - c0, fr = y - r0;
        const double top = at(c0, r0) + fc * (at(c0 + 1, r0) - at(c0, r0));
        const double bottom = at(c0, r0 + 1) + fc * (at(c0 + 1, r0 + 1) - at(c0, r0 + 1));
        return top + fr * (bottom - top);
    };
    if (cache_) {
        if (const fly::DetailTile* t = cache_->tile_at(x0, y0)) {
            const auto& z = t->heights();
            const int sx = t->samples_x();
            return bilinear([&](int c, int r) { return double(z[std::size_t(r) * std::size_t(sx) + std::size_t(c)]); },
                            sx, t->samples_y(), x0 - t->col0(), y0 - t->row0());
        }
        return double(fly::overview_height(*overview_, x0, y0));
    }
    const terrain::HeightGrid& grid = scene_->grid();
    return bilinear([&](int c, int r) { return double(grid.at(c, r)); }, grid.width, grid.height, x0, y0);
}

fly::CameraPose Flythrough::default_pose() const {
    const glm::dvec2 sw = frame_.to_metric(0.15 * (frame_.width() - 1), 0.85 * (frame_.height() - 1));
    const double top = z_top_;
    fly::CameraPose c;
    c.eye = {sw.x, sw.y, top + 500.0};
    double h = 0, p = 0;
    fly::direction_angles(glm::dvec3(-sw.x, -sw.y, ground_height_m({0, 0, 0}) - c.eye.z), h, p);
    c.heading_deg = h;
    c.pitch_deg = std::max(p, -25.0);
    return c;
}

void Flythrough::set_aircraft(const mesh::TriangleMesh& m, double scale, double forward_yaw_deg,
                              std::span<const blockers::Sphere> spheres) {
    aircraft_nodes_ = blockers::flatten_sphere_hierarchy(blockers::build_sphere_hierarchy(spheres));
    // Per node, the share of its bound's disc its leaves cover seen from below (the terrain is
    // under the aircraft): far from a node its sky cover is the bound's times this.
    aircraft_node_far_share_ = blockers::projected_cover_share(aircraft_nodes_);
    placed_spheres_.clear();
    aircraft_yaw_deg_ = forward_yaw_deg;
    std::vector<glm::vec4> v;
    v.resize(m.positions.size() * 3);
    // Each vertex's sky self-shadow, for the normal's side (in the normal's w) and the other
    // (in the colour's w): a function of the mesh alone (self_sky_shadow.hpp), so once here.
    const bool self_sky = settings_.aircraft_shadows && !aircraft_nodes_.empty();
    parallel_for(int(m.positions.size()), thread_count(0), [&](int k, int) {
        const std::size_t i = std::size_t(k);
        const glm::vec4 c = m.materials[m.material[i / 3]].base_color;
        const glm::dvec3 p(m.positions[i]), n(m.normals[i]);
        const double front = self_sky ? blockers::self_sky_share(aircraft_nodes_, aircraft_node_far_share_, p, n,
                                                                 settings_.aircraft_sky_detail)
                                      : 1.0;
        const double back = self_sky ? blockers::self_sky_share(aircraft_nodes_, aircraft_node_far_share_, p, -n,
                                                                settings_.aircraft_sky_detail)
                                     : 1.0;
        v[3 * i] = glm::vec4(m.positions[i], 1.0f);
        v[3 * i + 1] = glm::vec4(m.normals[i], float(front));
        v[3 * i + 2] = glm::vec4(glm::vec3(c), float(back));
    });
    renderer_->set_aircraft(v);
    aircraft_scale_ = scale;
    aircraft_triangles_ = m.triangle_count();
}

void Flythrough::update_aircraft_light(const glm::dvec3& centre) {
    // Level-0 texels, and the Scene's grid (a streamed DEM's overview: every 2^level-th texel).
    const double scale = overview_ ? double(1 << overview_->level) : 1.0;
    const glm::dvec2 texel0 = frame_.to_grid(centre.x, centre.y);
    const glm::dvec2 texel = texel0 / scale;
    const glm::dvec2 last0 = frame_.to_grid(aircraft_lit_at_.x, aircraft_lit_at_.y);
    const terrain::HeightGrid& g0 = overview_ ? grid0_ : scene_->grid();
    const int row = std::clamp(int(std::lround(texel0.y)), 0, g0.height - 1);
    const double spacing = std::min(g0.dx_m[std::size_t(row)], g0.dy_m[std::size_t(row)]);
    // A quarter level-0 texel, across or up: the horizons' march step (PointHorizonOptions).
    const double moved = std::max(glm::length(texel0 - last0), std::abs(centre.z - aircraft_lit_at_.z) / spacing);
    if (aircraft_lit_ && moved < 0.25) return;
    const glm::dvec3 sun(sun_dir_);
    std::vector<float> sigma(std::size_t(aircraft_lighting_->directions()));
    aircraft_lighting_->horizons(texel, centre.z, sigma.data());
    double sun_fraction = aircraft_lighting_->sun_fraction(texel, centre.z, sun, sun_radius_rad_);
    // A streamed DEM: the overview's horizons raised by the level-0 terrain of the tile under the
    // aircraft, if it is in (its window, without a base plane beyond it: the overview is there).
    if (const fly::DetailTile* tile = cache_ ? cache_->tile_at(texel0.x, texel0.y) : nullptr) {
        const terrain::HeightGrid near_grid = terrain::metric_view(tile->window());
        render::PointTerrainLightOptions o;
        o.directions = aircraft_lighting_->directions();
        o.base_plane = false;
        const render::PointTerrainLighting near(near_grid, o);
        const glm::dvec2 local = texel0 - glm::dvec2(tile->window_col0(), tile->window_row0());
        std::vector<float> near_sigma(sigma.size());
        near.horizons(local, centre.z, near_sigma.data());
        for (std::size_t d = 0; d < sigma.size(); ++d) sigma[d] = std::max(sigma[d], near_sigma[d]);
        sun_fraction = std::min(sun_fraction, near.sun_fraction(local, centre.z, sun, sun_radius_rad_));
    }
    aircraft_light_ = aircraft_lighting_->light_from(sigma.data(), sun_fraction, sky_sh_);
    aircraft_lit_ = true;
    aircraft_lit_at_ = centre;
}

void Flythrough::place_aircraft_spheres(const glm::dmat3& model_to_grid, const fly::CameraPose& aircraft,
                                        const fly::CameraPose& camera, FlyFrameUniforms& u) {
    placed_spheres_.clear();
    u.aircraft_bound = u.aircraft_shadow = u.aircraft_sky = glm::vec4(0.0f);
    if (aircraft_nodes_.empty() || !settings_.aircraft_shadows) return;
    // The rotation times a uniform scale: lengths scale by |first column|, and every node still
    // holds the spheres below it.
    const double scale = glm::length(model_to_grid[0]);
    sphere_upload_.clear();
    for (std::size_t j = 0; j < aircraft_nodes_.size(); ++j) {
        const blockers::FlatSphereNode& n = aircraft_nodes_[j];
        const blockers::Sphere p{aircraft.eye + model_to_grid * n.bound.center, n.bound.radius * scale};
        if (n.sphere >= 0) placed_spheres_.push_back(p);
        sphere_upload_.push_back(glm::vec4(glm::vec3(p.center - camera.eye), float(p.radius)));
        sphere_upload_.push_back(
            glm::vec4(float(n.skip), n.sphere >= 0 ? 1.0f : 0.0f, aircraft_node_far_share_[j], 0.0f));
    }
    renderer_->set_aircraft_spheres(sphere_upload_);
    const double bound_radius = aircraft_nodes_.front().bound.radius * scale;
    u.aircraft_bound = sphere_upload_.front();
    const double footprint = bound_radius / std::max(blockers::min_cap_sine(settings_.aircraft_min_solid_angle_sr), 1e-6);
    u.aircraft_shadow = glm::vec4(float(aircraft_nodes_.size()), float(footprint), float(sun_radius_rad_), 1.0f);
    u.aircraft_sky = glm::vec4(aircraft_node_far_share_.front(), float(settings_.aircraft_sky_detail), 0.0f, 0.0f);
}

void Flythrough::prepare(const fly::CameraPose& camera, FlyFrameUniforms& u, FlyFrameStats& stats,
                         const fly::CameraPose* aircraft) {
    fly::Projection proj;
    proj.horizontal_fov_deg = settings_.fov_deg;
    proj.width = renderer_->width();
    proj.height = renderer_->height();
    // The near plane follows the height above the ground: close enough to land, far enough
    // for depth precision (reversed Z keeps it either way).
    const double agl = camera.eye.z - ground_height_m(camera.eye);
    proj.near_m = std::clamp(0.25 * agl, 0.5, 20.0);  // the chased aircraft is 60 m away
    const glm::dmat4 vp = fly::eye_relative_view_projection(camera, proj);

    const Stopwatch watch;
    fly::CdlodView view;
    view.eye = camera.eye;
    view.eye_relative_view_projection = vp;
    view.viewport_height_px = proj.height;
    view.vertical_fov_rad = proj.vertical_fov_rad();
    tree_->select(view, selection_);
    stats.select_ms = watch.milliseconds();
    stats.tiles_loaded = 0;
    if (cache_) {
        const Stopwatch tiles;
        if (settings_.wait_for_tiles || !tiles_waited_) {
            tiles_waited_ = true;
            // Offscreen: the frame a window shows once the worker has brought every tile.
            while (selection_.coarse_fallbacks > 0) {
                const int loaded = cache_->load_requested_now();
                stats.tiles_loaded += std::size_t(loaded);
                tree_->select(view, selection_);
                if (loaded == 0) break;  // the budget holds no more
            }
        }
        const double k_px = view.viewport_height_px / (2.0 * std::tan(0.5 * view.vertical_fov_rad));
        const int finest_stored = tree_->stored_level();
        if (finest_stored > 0) cache_->set_prefetch(1.25 * tree_->range_m(finest_stored - 1, k_px));
        cache_->update(camera.eye);
        upload_tiles();
        assign_tile_slots();
        stats.coarse_fallbacks = selection_.coarse_fallbacks;
        stats.tiles_resident = cache_->resident();
        stats.tiles_pending = cache_->pending();
        stats.tiles_ms = tiles.milliseconds();
    }
    stats.patches = selection_.patches.size();
    stats.triangles = selection_.triangles;
    stats.screen_error_px = selection_.screen_error_px;
    stats.screen_error_max_px = selection_.screen_error_max_px;

    const fly::CameraAxes axes = fly::camera_axes(camera.heading_deg, camera.pitch_deg, camera.roll_deg);
    u.view_projection = glm::mat4(vp);
    u.eye = glm::vec4(glm::vec3(camera.eye), float(sun_radius_rad_));
    u.grid = glm::vec4(float(frame_.width()), float(frame_.height()), float(frame_.centre_col()),
                       float(settings_.haze_km * 1000.0));
    u.sun_direction = glm::vec4(sun_dir_, float(sun_cos_radius_));
    u.sun_radiance = glm::vec4(sun_radiance_, float(exposure_));
    const double tan_h = std::tan(0.5 * radians(settings_.fov_deg));
    const double tan_v = std::tan(0.5 * proj.vertical_fov_rad());
    u.camera_right = glm::vec4(glm::vec3(axes.right), float(tan_h));
    u.camera_up = glm::vec4(glm::vec3(axes.up), float(tan_v));
    u.camera_forward = glm::vec4(glm::vec3(axes.forward), 0.0f);
    if (aircraft != nullptr && aircraft_triangles_ > 0) {
        update_aircraft_light(aircraft->eye);
        for (int i = 0; i < 16; ++i) u.sky_sh[i] = glm::vec4(aircraft_light_.visible_sky[std::size_t(i)], 0.0f);
        u.aircraft_light = glm::vec4(aircraft_light_.sun_fraction, 0.0f, 0.0f, 0.0f);
        mesh::Placement p;
        p.heading_deg = aircraft->heading_deg;
        p.pitch_deg = aircraft->pitch_deg;
        p.roll_deg = aircraft->roll_deg;
        // The model's nose turned onto +y, the placement's forward, first.
        const double yaw = radians(aircraft_yaw_deg_);
        const glm::dmat3 to_forward(std::cos(yaw), std::sin(yaw), 0.0, -std::sin(yaw), std::cos(yaw), 0.0, 0.0, 0.0, 1.0);
        const glm::dmat3 r = mesh::placement_rotation(p) * to_forward * aircraft_scale_;
        glm::dmat4 m(r);
        m[3] = glm::dvec4(aircraft->eye - camera.eye, 1.0);
        renderer_->set_aircraft_transform(glm::mat4(m), true);
        stats.triangles += aircraft_triangles_;
        place_aircraft_spheres(r, *aircraft, camera, u);
    } else {
        renderer_->set_aircraft_transform(glm::mat4(1.0f), false);
        placed_spheres_.clear();
        u.aircraft_bound = u.aircraft_shadow = u.aircraft_sky = glm::vec4(0.0f);
    }
    u.overview = glm::vec4(float(scene_->grid().width), float(scene_->grid().height),
                           overview_ ? float(1 << overview_->level) : 1.0f, float(tree_->stored_level()));
    const light::SkyGrid& sg = sky_table_.grid();
    u.sky_table = glm::vec4(float(sg.azimuths), float(sg.elevations), float(sg.first_el), float(sg.last_el));
}

}  // namespace ts::gpu
