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
#include "core/render/tone_map.hpp"
#include "core/util/angles.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/progress_bar.hpp"
#include "core/util/stopwatch.hpp"

namespace ts::gpu {
namespace {

// rgb as three halves; `extra` goes in the fourth.
std::uint32_t pack_rgb(glm::vec3 c, std::uint32_t& second, float extra = 0.0f) {
    const bool finite = std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z);
    const glm::vec3 v = finite ? glm::max(c, glm::vec3(0.0f)) : glm::vec3(0.0f);
    second = glm::packHalf2x16(glm::vec2(v.z, extra));
    return glm::packHalf2x16(glm::vec2(v.x, v.y));
}

std::unique_ptr<render::Scene> make_scene(const dem::Dem& dem, const FlySettings& s) {
    render::SceneOptions options;
    options.view = render::ViewKind::map;
    options.sky = light::parse_sky_options(s.sky);
    options.renderer.directions = s.directions;
    ProgressBar bar("visibility", std::uint64_t(dem.width) * std::uint64_t(dem.height) * std::uint64_t(s.directions),
                    "rays");
    options.renderer.progress = &bar;
    auto scene = std::make_unique<render::Scene>(dem, options);
    bar.finish();
    return scene;
}

}  // namespace

Flythrough::Flythrough(const dem::Dem& dem, const FlySettings& settings, Context& context)
    : dem_(dem), settings_(settings), scene_(make_scene(dem, settings)), frame_(scene_->grid()), context_(context) {
    tree_ = std::make_unique<fly::CdlodTree>(scene_->grid(), frame_, settings_.lod);
    std::vector<float> rows(std::size_t(frame_.height()) * 2);
    for (int r = 0; r < frame_.height(); ++r) {
        rows[std::size_t(2 * r)] = float(frame_.row_dx_m()[std::size_t(r)]);
        rows[std::size_t(2 * r + 1)] = float(frame_.row_north_m()[std::size_t(r)]);
    }
    FlyTerrain terrain;
    terrain.width = frame_.width();
    terrain.height = frame_.height();
    terrain.heights = scene_->grid().z;
    terrain.rows = rows;
    terrain.patch_quads = settings_.lod.patch_quads;
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
    packed_sun_.resize(2 * texels);
    // The sun's part of each texel's radiance, albedo/pi E_sun max(0, n.s) times the sun's
    // visibility (FrameRenderer's diffuse sun term; the few specular and water texels' sun
    // terms stay in the rest): what an aircraft's shadow takes away; with the texel's open-sky
    // fraction, which scales what it takes of the rest.
    const render::MaterialRaster& m = scene_->state().materials();
    const render::NormalField& nf = scene_->state().normals();
    const std::vector<float>& sun_vis = scene_->renderer().sun_visibility();
    const glm::vec3 s = glm::vec3(render::sun_direction(sun_));
    const glm::vec3 e = sky.sun().irradiance * float(1.0 / kPi);
    for (std::size_t t = 0; t < texels; ++t) {
        const glm::vec3 c = radiance_.rgb[t];
        const float v = sun_vis[t] == sun_vis[t] ? sun_vis[t] : 0.0f;
        const float w = v * std::max(0.0f, nf.x[t] * s.x + nf.y[t] * s.y + nf.z[t] * s.z);
        const glm::vec3 sun_part = glm::min(glm::vec3(m.albedo_r[t], m.albedo_g[t], m.albedo_b[t]) * e * w, c);
        packed_[2 * t] = pack_rgb(c, packed_[2 * t + 1]);
        packed_sun_[2 * t] = pack_rgb(sun_part, packed_sun_[2 * t + 1], open_sky_[t]);
    }
    renderer_->set_radiance(packed_);
    renderer_->set_sun_radiance(packed_sun_);
    sky_table_ = fly::make_sky_table(sky);
    sky_sh_ = light::project_sky_sh(sky);
    aircraft_light_ = {sky_sh_, 1.0f};
    aircraft_lit_ = false;
    renderer_->set_sky(sky_table_.rgb);
    const light::SunDisc disc = sky.sun();
    sun_dir_ = glm::vec3(disc.direction);
    sun_radiance_ = fly::sun_disc_radiance(disc);
    sun_cos_radius_ = std::cos(disc.angular_radius_rad);
    sun_radius_rad_ = disc.angular_radius_rad;
    exposure_ = render::image_exposure_scale(radiance_, render::Exposure{});
    return watch.milliseconds();
}

fly::CameraPose Flythrough::pose_of(const fly::FlightPose& p) const {
    const glm::dvec2 px = dem_.georef.lonlat_to_pixel({p.lon_deg, p.lat_deg});
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
    return dem_.georef.pixel_to_lonlat(g.x + 0.5, g.y + 0.5);
}

fly::FlightPose Flythrough::flight_pose_of(const fly::CameraPose& c, double t_s) const {
    const glm::dvec2 ll = lonlat_of(c.eye);
    return {t_s, ll.x, ll.y, c.eye.z, c.heading_deg, c.pitch_deg, c.roll_deg};
}

double Flythrough::ground_height_m(const glm::dvec3& eye) const {
    const glm::dvec2 g = frame_.to_grid(eye.x, eye.y);
    const terrain::HeightGrid& grid = scene_->grid();
    const double x = std::clamp(g.x, 0.0, double(grid.width - 1)), y = std::clamp(g.y, 0.0, double(grid.height - 1));
    const int c0 = std::min(int(x), grid.width - 2), r0 = std::min(int(y), grid.height - 2);
    const double fc = x - c0, fr = y - r0;
    const double top = grid.at(c0, r0) + fc * (grid.at(c0 + 1, r0) - grid.at(c0, r0));
    const double bottom = grid.at(c0, r0 + 1) + fc * (grid.at(c0 + 1, r0 + 1) - grid.at(c0, r0 + 1));
    return top + fr * (bottom - top);
}

fly::CameraPose Flythrough::default_pose() const {
    const glm::dvec2 sw = frame_.to_metric(0.15 * (frame_.width() - 1), 0.85 * (frame_.height() - 1));
    double top = 0;
    for (float z : scene_->grid().z) top = std::max(top, double(z));
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
    const glm::dvec2 texel = frame_.to_grid(centre.x, centre.y);
    const glm::dvec2 last = frame_.to_grid(aircraft_lit_at_.x, aircraft_lit_at_.y);
    const terrain::HeightGrid& grid = scene_->grid();
    const int row = std::clamp(int(std::lround(texel.y)), 0, grid.height - 1);
    const double spacing = std::min(grid.dx_m[std::size_t(row)], grid.dy_m[std::size_t(row)]);
    // A quarter texel, across or up: the horizons' march step (PointHorizonOptions).
    const double moved = std::max(glm::length(texel - last), std::abs(centre.z - aircraft_lit_at_.z) / spacing);
    if (aircraft_lit_ && moved < 0.25) return;
    aircraft_light_ = aircraft_lighting_->light(texel, centre.z, sky_sh_, glm::dvec3(sun_dir_), sun_radius_rad_);
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
    stats.patches = selection_.patches.size();
    stats.triangles = selection_.triangles;
    stats.screen_error_px = selection_.screen_error_px;
    stats.screen_error_max_px = selection_.screen_error_max_px;

    const fly::CameraAxes axes = fly::camera_axes(camera.heading_deg, camera.pitch_deg, camera.roll_deg);
    u.view_projection = glm::mat4(vp);
    u.eye = glm::vec4(glm::vec3(camera.eye), 0.0f);
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
    u.sky_table = glm::vec4(float(sky_table_.azimuths), float(sky_table_.elevations), float(sky_table_.lowest_rad),
                            float(sky_table_.highest_rad));
}

}  // namespace ts::gpu
