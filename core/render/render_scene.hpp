#pragma once
// Everything `render`, `relight` and `bench relight` share: a DEM turned once into normals,
// materials, visibility and transfer vectors (shading_state.hpp), a target (render_target.hpp),
// then frames for any number of sun positions and skies.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/dem/dem.hpp"
#include "core/light/sky.hpp"
#include "core/light/utc_time.hpp"
#include "core/render/frame_renderer.hpp"
#include "core/material/material.hpp"
#include "core/material/palette_materials.hpp"
#include "core/render/mesh_lighting.hpp"
#include "core/render/mesh_view.hpp"
#include "core/render/perspective_view.hpp"
#include "core/render/render_target.hpp"
#include "core/render/scene_blockers.hpp"
#include "core/render/shading_state.hpp"
#include "core/light/sky_table.hpp"
#include "core/render/view_shading.hpp"
#include "core/render/relief_contrast.hpp"
#include "core/render/tone_map.hpp"
#include "core/terrain/height_grid.hpp"

namespace ts::render {

// A georeferenced extent to render: [x0, x1] x [y0, y1] in `crs` (EPSG:3857, a PROJ string,
// WKT; empty = the DEM's CRS), north up, width x height pixels.
struct ExtentRequest {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    std::string crs;
    int width = 512, height = 512;
};
// The extent's georef (pixel-is-area, north up). Throws ts::InputError for an empty extent or
// an unknown CRS.
geo::Georef extent_georef(const ExtentRequest& extent, const geo::Georef& dem_georef);

// map: the DEM grid (or resampled to map_width x map_height); extent: a georeferenced extent in
// any CRS (SceneOptions::extent); perspective: a camera.
enum class ViewKind { map, extent, perspective };

// How much of the land albedos' luminance contrast a picture keeps (material.hpp,
// compress_albedo_contrast): half, in log terms, so the relief reads first (docs/rendering.md).
inline constexpr double kDefaultAlbedoContrast = 0.5;

struct SceneOptions {
    std::string materials;           // a land-cover GeoTIFF of WorldCover codes, or empty (none)
    // The land colours (a palette, percent stops fitted to this DEM's heights unless fitted
    // already) and the snow line (palette_materials.hpp).
    ColorDesign colors;
    std::string albedo;              // RGB orthophoto GeoTIFF, or empty
    double albedo_contrast = kDefaultAlbedoContrast;  // compress_albedo_contrast (material.hpp)
    // Maps and extents: the shading stretched (relief_contrast.hpp); by default the physical picture.
    ReliefContrast relief_contrast{.automatic = false};
    MaterialRule rule;               // water: sea level and flatness
    RendererOptions renderer;
    light::SkyOptions sky;
    ViewKind view = ViewKind::map;
    std::optional<Camera> camera;    // perspective; default_camera() if empty
    PerspectiveOptions perspective;
    // Map: output size (0 = the DEM grid); the texels are resampled bilinearly.
    int map_width = 0, map_height = 0;
    // Extent: the picture's bounds in a CRS (empty: the DEM's) and its size in pixels.
    std::optional<ExtentRequest> extent;
    // Meshes over the DEM: their spheres shadow the terrain's sky and sun (docs/blockers.md).
    std::vector<SceneMesh> meshes;
    blockers::SphereBlockerOptions blocker_options;
    // Perspective views draw the meshes that have triangles, lit per vertex by the terrain's
    // horizons from them and shadowed by their own spheres (mesh_lighting.hpp); these turn the
    // two parts off.
    bool mesh_terrain_shadow = true;
    bool mesh_self_shadow = true;
};

// Where the sun is computed for a DEM: its centre (lon/lat from its georef) at its mean height.
struct SunSite {
    double longitude_deg = 0, latitude_deg = 0, height_m = 0;
};
SunSite sun_site(const dem::Dem& dem);
// The sun seen from `site` at `time` (NREL SPA, standard atmosphere at the site's height).
SunState sun_at(const SunSite& site, light::UtcTime time);

// A DEM made ready for frames: the view-independent shading state (computed once), one
// target and the view shading it needs, and a frame renderer; then frames for any number of
// sun positions and skies.
class Scene {
public:
    // The Dem (voids filled, void_mask kept) must outlive the scene. Computes the shading state.
    Scene(const dem::Dem& dem, const SceneOptions& options);
    ~Scene();

    // Sun position at the DEM's centre (lon/lat from its georef, its mean height) at `time`,
    // on the grid (on_grid): what render() takes.
    SunState sun_at(light::UtcTime time) const;
    // A sun of true azimuth (sun_position's, or the user's --sun-azimuth) on this DEM's grid:
    // turned by where true north lies at its centre (0 on geographic and Web Mercator grids;
    // the meridian convergence on a projected one, e.g. -2.1 degrees 3 degrees east of a UTM
    // zone's meridian at 45 N).
    SunState on_grid(const SunState& true_sun) const;
    double grid_north_deg() const { return grid_north_deg_; }

    // Renders one frame: the sky from options.sky for this sun (on the grid: on_grid), per-texel
    // radiance, then the target's picture. `image` keeps its storage from frame to frame.
    void render(const SunState& sun, LinearImage& image);
    // Mesh k (of options.meshes) moves to `placement` for the frames that follow: its spheres
    // are placed again and the shading state recomputes only its old and new footprints
    // (ShadingState::move_mesh). Map and extent views (a drawn mesh does not move: InputError
    // in a perspective view). Throws ts::InputError for a placement off the DEM. Returns the
    // rectangle of texels recomputed.
    visibility::TexelRect move_mesh(std::size_t k, const mesh::Placement& placement);
    // The blockers' part recomputed over the whole grid (ShadingState::recompute_blockers).
    void recompute_blockers() { state_->recompute_blockers(); }
    // The relief contrast the last frame got (k = 1: none; relief_contrast.hpp).
    ReliefContrastApplied last_relief_contrast() const { return last_relief_; }
    // The sky of the last frame (for its description).
    const light::Sky* last_sky() const { return sky_.get(); }

    // The share of the cosine-weighted sky each texel sees (open_sky_fraction.hpp). It renders a
    // frame of its own (a uniform sky, no sun): the renderer's sun visibility is then that frame's.
    std::vector<float> open_sky_fraction();

    const ShadingState& state() const { return *state_; }
    const FrameRenderer& renderer() const { return *renderer_; }
    const RenderTarget& target() const { return *target_; }
    const terrain::HeightGrid& grid() const { return *grid_; }
    const Camera* camera() const;
    // The per-texel radiance of the last frame (a map on the DEM grid is rendered straight into
    // the image: there it is the image's rgb, and this is empty).
    const std::vector<glm::vec3>& texel_radiance() const { return texel_radiance_; }
    const SceneOptions& options() const { return options_; }
    // The meshes placed on the grid (empty without --mesh), and what placing them found
    // (one line each: a mesh below the terrain).
    const blockers::SphereBlockers& blockers() const { return blockers_; }
    const std::vector<std::string>& warnings() const { return warnings_; }
    // Perspective views: each drawn mesh's per-vertex lighting, and where they cover the view.
    const std::vector<std::unique_ptr<MeshLighting>>& mesh_lighting() const { return mesh_lighting_; }
    const MeshView* mesh_view() const { return mesh_view_.get(); }

private:
    // Perspective views: per-vertex lighting of the meshes with triangles, rasterised into `view`.
    void attach_mesh_views(const PerspectiveView& view);

    const dem::Dem& dem_;
    SceneOptions options_;
    double grid_north_deg_ = 0.0;  // where true north lies on the grid at the DEM's centre
    std::unique_ptr<terrain::HeightGrid> grid_;
    blockers::SphereBlockers blockers_;  // the state points to it: declared before the state
    std::vector<std::string> warnings_;
    std::unique_ptr<ShadingState> state_;
    std::unique_ptr<RenderTarget> target_;
    ViewShading view_;
    std::unique_ptr<FrameRenderer> renderer_;
    std::unique_ptr<light::Sky> sky_;
    std::vector<glm::vec3> texel_radiance_;
    std::unique_ptr<PixelSunBlockers> pixel_blockers_;  // perspective views and magnified maps with meshes
    ReliefContrastApplied last_relief_;
    std::vector<std::unique_ptr<MeshLighting>> mesh_lighting_;
    std::unique_ptr<MeshView> mesh_view_;
    std::vector<std::vector<glm::vec3>> mesh_radiance_;  // per frame, per mesh
};

// Sun position at the DEM's centre (lon/lat from its georef, its mean height) at `time`.
SunState sun_at_dem_centre(const dem::Dem& dem, light::UtcTime time);

// Writes a picture by extension: .png / .tif / .tiff (8-bit sRGB after exposure and the
// filmic curve; a .tif of a map view is a Cloud-Optimized GeoTIFF (core/raster/cog_writer.hpp)
// georeferenced with `georef`, whose size may differ from the image's: it is scaled), .exr
// (linear, no tone mapping). With alpha: RGBA. Atomic.
// Returns the exposure scale used (1 for EXR).
double write_image(const std::string& path, const LinearImage& image, const Exposure& exposure,
                   const geo::Georef* georef);
// The exposure scale an image gets (auto: from the log-average luminance of its covered pixels).
double image_exposure_scale(const LinearImage& image, const Exposure& exposure);
// Checks the extension before any work; throws ts::InputError naming the path.
void check_image_extension(const std::string& path);

}  // namespace ts::render
