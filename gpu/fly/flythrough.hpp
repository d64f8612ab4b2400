#pragma once
// What `terrashade fly`, `bench fly` and the tests share: a DEM made ready to fly over. Once: the
// view-independent shading state (render::Scene on the DEM grid), the CDLOD tree, the Vulkan
// renderer with the heights uploaded. On each change of time: the per-texel radiance of that
// sun and sky (the fused diffuse pass over the cached transfer vectors) and the sky table,
// uploaded. Each frame: the LOD selection for the camera and the frame's uniforms.
//
// A DEM too large to hold is streamed (the dem::DemSource constructor): the Scene shades its
// overview (every 2^level-th texel, core/fly/terrain_overview.hpp), which the CDLOD levels from
// that level up draw; the finer levels draw the level-0 detail tiles resident near the camera
// (core/fly/detail_tile_cache.hpp), each shaded on its own window with the overview's far field
// beyond it, loaded on a worker thread within the memory budget and lit again only when the sun
// changes.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/render/bounce_transfer.hpp"
#include "core/render/horizon_sky_light.hpp"
#include "core/blockers/sphere_blocker.hpp"
#include "core/blockers/sphere_hierarchy.hpp"
#include "core/dem/dem.hpp"
#include "core/material/palette_materials.hpp"
#include "core/fly/camera_rig.hpp"
#include "core/fly/cdlod_tree.hpp"
#include "core/fly/flight_path.hpp"
#include "core/fly/grid_frame.hpp"
#include "core/fly/fly_sky.hpp"
#include "core/fly/detail_tile_cache.hpp"
#include "core/fly/terrain_overview.hpp"
#include "core/dem/dem_source.hpp"
#include "core/light/sky.hpp"
#include "core/light/utc_time.hpp"
#include "core/mesh/triangle_mesh.hpp"
#include "core/render/point_terrain_light.hpp"
#include "core/render/render_scene.hpp"
#include "gpu/context.hpp"
#include "gpu/fly/fly_renderer.hpp"

namespace ts::visibility {
class FarField;
}

namespace ts::gpu {

struct FlySettings {
    std::string sky = "clear";
    ts::render::ColorDesign colors;  // --colors, --snow-line (percent stops fitted to the DEM flown)
    int directions = 16;
    ts::render::BounceSettings bounce;  // light bounced off the terrain (--bounces)
    ts::render::SkyLightSettings sky_light;  // --sky-light, --sky-sectors
    fly::CdlodOptions lod;
    double haze_km = 250.0;
    double fov_deg = 60.0;
    // --shadow-detail: true (pixel) places the sun's shadow edges inside texels, where each
    // fragment's interpolated horizon in the sun's azimuth crosses the sun; false (texel)
    // blends the texels' visible shares of the disc (texel-wide ramps along the texel lines).
    bool pixel_sun_shadows = true;
    int width = 960, height = 540;
    // The aircraft's spheres shadow the terrain (sun and sky) and the aircraft itself (sun).
    bool aircraft_shadows = true;
    // The sky footprint: receivers farther than r / sin(theta_min) from the spheres' bound of
    // radius r, 2 pi (1 - cos theta_min) = this solid angle, are not darkened (as
    // blockers::SphereBlockerOptions::min_solid_angle_sr).
    double aircraft_min_solid_angle_sr = 0.01;
    // Where the root sphere hides more than this fraction of a receiver's cosine-weighted sky
    // the spheres' covers are combined one by one; farther the root's cover times the share of
    // it the spheres keep from afar (their far limit), one evaluation a fragment.
    double aircraft_sky_detail = 0.05;
    // Streamed DEMs: what the overview, the far field and the detail tiles may hold in all; the
    // overview's level (0: the finest whose shading state takes at most a quarter of the budget).
    std::size_t memory_budget_bytes = std::size_t(4) << 30;
    int overview_level = 0;
    int detail_halo = 64;
    // Offscreen frames wait for every tile their view asks for (a window waits at its first frame
    // only, then draws coarser until the worker brings them).
    bool wait_for_tiles = false;
};

// The memory a DEM takes flown over whole (its shading state and device copy: 273 bytes a texel
// measured, plus ~90 MB).
std::size_t whole_fly_bytes(std::int64_t texels);

struct FlyFrameStats {
    double select_ms = 0;
    std::size_t patches = 0, triangles = 0;
    double screen_error_px = 0, screen_error_max_px = 0;
    // Streamed DEMs: patches drawn coarser for want of their tile, tiles resident and loading,
    // tiles loaded by this frame (waiting offscreen) and the time that took.
    std::size_t coarse_fallbacks = 0, tiles_resident = 0, tiles_pending = 0, tiles_loaded = 0;
    double tiles_ms = 0;
};

class Flythrough {
public:
    // `context` (made with the settings' window extensions, if any) must outlive the flight.
    Flythrough(const dem::Dem& dem, const FlySettings& settings, Context& context);
    // A DEM streamed by tile (`source` must outlive the flight).
    Flythrough(const dem::DemSource& source, const FlySettings& settings, Context& context);
    ~Flythrough();

    bool streamed() const { return overview_ != nullptr; }
    const fly::TerrainOverview* overview() const { return overview_.get(); }
    const fly::DetailTileCache* detail_tiles() const { return cache_.get(); }

    Context& context() { return context_; }
    FlyRenderer& renderer() { return *renderer_; }
    const fly::GridFrame& frame() const { return frame_; }
    const fly::CdlodTree& tree() const { return *tree_; }
    // The Scene shading the DEM (streamed: its overview).
    const ts::render::Scene& scene() const { return *scene_; }
    const FlySettings& settings() const { return settings_; }

    // Relights when `time` differs from the last one (returns the milliseconds it took, 0 if not).
    double set_time(light::UtcTime time);
    light::UtcTime time() const { return time_; }
    const ts::render::SunState& sun() const { return sun_; }

    // A path pose in the grid frame, and back (for recording).
    fly::CameraPose pose_of(const fly::FlightPose& p) const;
    fly::FlightPose flight_pose_of(const fly::CameraPose& c, double t_s) const;
    glm::dvec2 lonlat_of(const glm::dvec3& eye) const;
    // The terrain's height under a metric position (bilinear, clamped onto the grid).
    double ground_height_m(const glm::dvec3& eye) const;
    // A start above the DEM's south-west, looking over its centre.
    fly::CameraPose default_pose() const;

    // The aircraft drawn at the path's pose (its model frame in metres, times `scale`), its nose
    // turned by `forward_yaw_deg` (counter-clockwise about up) onto the model's +y first;
    // `spheres` (its decomposition, the same model frame) cast its shadows (none: no shadows).
    void set_aircraft(const mesh::TriangleMesh& mesh, double scale, double forward_yaw_deg,
                      std::span<const blockers::Sphere> spheres = {});
    // The aircraft's spheres as the last prepared frame placed them: grid-frame metres (the
    // frame's metric coordinates, heights above the datum), before any curvature drop.
    const std::vector<blockers::Sphere>& placed_aircraft_spheres() const { return placed_spheres_; }
    bool has_aircraft() const { return aircraft_triangles_ > 0; }
    // Each texel's open-sky fraction (core/render/open_sky_fraction.hpp; after the first
    // set_time): the aircraft's sky shadow takes ts_open_sky_share of a texel's sky light.
    const std::vector<float>& open_sky_fraction() const { return open_sky_; }
    // The terrain's light at the aircraft's centre in the last prepared frame (open sky and the
    // whole sun before any).
    const ts::render::PointTerrainLight& aircraft_terrain_light() const { return aircraft_light_; }

    // Selects the terrain for this camera and fills the frame's uniforms; `aircraft`: where the
    // aircraft is this frame (nullptr: not drawn).
    void prepare(const fly::CameraPose& camera, FlyFrameUniforms& uniforms, FlyFrameStats& stats,
                 const fly::CameraPose* aircraft = nullptr);
    const std::vector<fly::CdlodPatch>& patches() const { return selection_.patches; }

private:
    void init_renderer();
    void assign_tile_slots();
    void upload_tiles();

    FlySettings settings_;
    const geo::Georef* georef0_ = nullptr;  // the level-0 grid's
    // Streamed: the overview, its points as the Scene's DEM, the far field, the tiles.
    std::unique_ptr<fly::TerrainOverview> overview_;
    std::unique_ptr<ts::visibility::FarField> far_;
    std::unique_ptr<fly::DetailTileCache> cache_;
    const dem::DemSource* source_ = nullptr;
    terrain::HeightGrid grid0_;  // level-0 spacing of a streamed DEM (no heights)
    double z_top_ = 0;
    bool tiles_waited_ = false;  // the first frame waits for its tiles, even in a window
    std::unique_ptr<ts::render::Scene> scene_;
    fly::GridFrame frame_;
    std::unique_ptr<fly::CdlodTree> tree_;
    Context& context_;
    std::unique_ptr<FlyRenderer> renderer_;
    light::UtcTime time_{};
    bool lit_ = false;
    ts::render::SunState sun_;
    glm::vec3 sun_dir_{0, 0, 1}, sun_radiance_{0.0f};
    double sun_cos_radius_ = 1.0;
    double exposure_ = 1.0;
    light::SkyTable sky_table_{fly::fly_sky_grid()};
    light::SkySh sky_sh_{};
    double aircraft_scale_ = 1.0, aircraft_yaw_deg_ = 0.0;
    std::size_t aircraft_triangles_ = 0;
    // The spheres' hierarchy in depth-first order (model frame; [0] holds them all).
    std::vector<blockers::FlatSphereNode> aircraft_nodes_;
    // Per node, the share of its bound's sky cover its leaves keep from afar: the sky walk stops
    // at a node whose cap is small (the root's share goes in the frame's uniforms).
    std::vector<float> aircraft_node_far_share_;
    std::vector<blockers::Sphere> placed_spheres_;
    std::vector<glm::vec4> sphere_upload_;
    void place_aircraft_spheres(const glm::dmat3& model_to_grid, const fly::CameraPose& aircraft,
                                const fly::CameraPose& camera, FlyFrameUniforms& uniforms);
    // The terrain's horizons from the aircraft, recomputed only when it moved by more than a
    // fraction of a texel or the sun changed (set_time clears aircraft_lit_).
    void update_aircraft_light(const glm::dvec3& centre);
    std::unique_ptr<ts::render::PointTerrainLighting> aircraft_lighting_;
    ts::render::PointTerrainLight aircraft_light_;
    bool aircraft_lit_ = false;
    glm::dvec3 aircraft_lit_at_{0.0};
    double sun_radius_rad_ = 0.0;
    fly::CdlodSelection selection_;
    ts::render::LinearImage radiance_;
    std::vector<std::uint32_t> packed_, packed_sun_;
    // Each texel's open-sky fraction (core/render/open_sky_fraction.hpp), packed beside its sun
    // radiance: the aircraft's sky shadow takes cover / open of the texel's sky light.
    std::vector<float> open_sky_;
};

}  // namespace ts::gpu
