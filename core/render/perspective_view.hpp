#pragma once
// A camera view of the shaded terrain: each pixel's ray is marched over the height field once
// (the camera does not move while the light changes), then every frame only looks up the
// per-texel radiance at the hit (bilinear) or the sky where the ray misses. The surface is the
// smooth one through the texel centres (core/terrain/smooth_surface.hpp), and the sun's
// diffuse term is shaded with each pixel's own normal there: a close view shows the relief at
// the DEM's resolution instead of a bilinear blur of per-texel shading.
//
// Frame: the DEM's local metric grid around the camera (east/north metres from the per-row
// spacing, heights above the DEM datum), with the Earth's curvature (and standard refraction,
// R_eff = R / (1 - 0.13)) dropping terrain at horizontal distance s by s^2 / (2 R_eff).
// Marching: surface_march.hpp (a max pyramid over the patches lets a ray skip any cell it
// passes above; inside a patch the crossing is bracketed by sub-steps and refined by bisection).
// Sun shadows (PerspectiveOptions::pixel_sun_shadows): each frame marches a ray towards the sun
// over the same surface from every lit hit whose patch's texels the frame's shadows split, for
// the visible share of the disc, so a shadow's edge falls where it does at the pixel, not where
// a bilinear blend of the texels' puts it; the meshes' shadows are found at every hit.
// Silhouettes (PerspectiveOptions::edge_samples): a pixel whose ray and a neighbour's disagree
// on hitting the terrain, or hit it at distances far apart, casts a grid of rays across its
// area; the share that hits weighs the terrain's colour against the sky's, and near terrain's
// share against the far terrain's behind it. One ray per pixel drew a near-level skyline
// against a bright sky as a staircase (runs of 40-80 pixels, one-pixel steps), and a ridge's
// outline against the slopes behind it likewise.
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/geo/georef.hpp"
#include "core/light/sky_table.hpp"
#include "core/render/pixel_sun_shading.hpp"
#include "core/render/surface_march.hpp"
#include "core/terrain/height_grid.hpp"

namespace ts::render {

struct Camera {
    double lon_deg = 0, lat_deg = 0;
    double height_m = 0;     // above the DEM's vertical datum (the same heights as the DEM)
    double heading_deg = 0;  // clockwise from north
    double pitch_deg = -20;  // above the horizontal; negative looks down
    double fov_deg = 60;     // horizontal field of view
};
// "lon,lat,height,heading,pitch,fov". Throws ts::InputError on a bad list or range.
Camera parse_camera(std::string_view text);
std::string format_camera(const Camera& c);

// The default: from beyond the DEM's south-west corner, 40% of the DEM's diagonal back from
// its centre and high enough to see over it, looking at the centre (heading ~45 deg, pitch
// down to the centre). docs/rendering.md shows it.
Camera default_camera(const terrain::HeightGrid& grid, const geo::Georef& georef);

struct PerspectiveOptions {
    int width = 960, height = 540;
    // Aerial perspective: transmittance exp(-distance / haze_distance_m) towards the sky's
    // horizon radiance in the ray's azimuth; 0 turns haze off.
    double haze_distance_m = 250000.0;
    bool curvature = true;
    // Sun shadows found per pixel by a ray towards the sun (the header) rather than blended
    // from the texels' visible fractions, whose edges are a texel wide and stair-stepped.
    bool pixel_sun_shadows = true;
    // Rays across each silhouette pixel, N x N (`--edge-samples`; 1 = the centre's alone).
    int edge_samples = 4;
    int threads = 0;
};

class PerspectiveView {
public:
    PerspectiveView(const terrain::HeightGrid& grid, const geo::Georef& georef, const Camera& camera,
                    const PerspectiveOptions& options);

    int width() const { return options_.width; }
    int height() const { return options_.height; }
    // Unit direction from each DEM texel towards the camera (for specular and water).
    std::vector<glm::vec3> view_directions() const;
    // Pixels whose ray hit the terrain.
    std::size_t hit_count() const;
    // Whether the camera starts below the terrain (every ray then hits at once).
    bool camera_below_terrain() const { return below_terrain_; }
    // The terrain's height under the camera (clamped onto the DEM), metres above its datum.
    double ground_height_m() const { return ground_m_; }

    // Composes a frame: per-texel radiance (width*height of the grid) sampled at the hits, the
    // sky (and the sun's disc) elsewhere. With `sun_term` the radiance's diffuse sun term is
    // taken out at the texels and shaded with the pixel's normal instead. `image` is resized to
    // width*height once.
    void compose(const glm::vec3* texel_radiance, const TexelSunTerm* sun_term, const light::SkyTable& sky,
                 const glm::vec3& sun_dir, const glm::vec3& sun_radiance, double sun_cos_radius,
                 std::vector<glm::vec3>& image) const;

    // The camera's frame, for drawing other geometry into the same picture (mesh_view.hpp):
    // position in (texel-centre col, row, height m), the ENU metres per texel at its row, the
    // curvature factor, its axes and the half-extents of the image plane at unit distance.
    struct Frame {
        glm::dvec3 position{0.0};
        double dx = 1, dy = 1, curvature = 0;
        glm::dvec3 forward{0, 1, 0}, right{1, 0, 0}, up{0, 0, 1};
        double half_width = 1, half_height = 1;
    };
    const Frame& frame() const { return frame_; }
    // Distance in metres along pixel k's ray to the terrain (infinity where it misses).
    float terrain_distance(std::size_t k) const { return pixels_[k].distance; }
    // The share of pixel k the terrain covers: 1 or 0, fractional on its silhouette.
    float terrain_coverage(std::size_t k) const {
        const Pixel& p = pixels_[k];
        return p.x < 0 ? 0.0f : p.behind < 0 ? p.coverage : p.coverage + behind_[std::size_t(p.behind)].coverage;
    }
    // The share of pixel k its nearest surface covers: below 1 on a silhouette against the sky
    // and where near terrain stands in front of far terrain.
    float front_coverage(std::size_t k) const { return pixels_[k].x >= 0 ? pixels_[k].coverage : 0.0f; }
    glm::vec3 ray_direction(std::size_t k) const { return pixels_[k].dir; }
    // The smooth surface's unit normal (ENU) where pixel k's ray hits ((0, 0, 1) on a miss).
    glm::vec3 surface_normal(std::size_t k) const { return pixels_[k].normal; }
    // A surface's radiance `c` at `distance` along a ray `dir` seen through the haze.
    glm::vec3 haze(const glm::vec3& c, const glm::vec3& dir, double distance, const light::SkyTable& sky) const;

private:
    struct Pixel {
        float x = -1, y = -1;        // hit in texel-centre coordinates, x < 0 = miss
        float transmittance = 1;     // haze
        float distance = std::numeric_limits<float>::infinity();  // to the hit along the ray, metres
        glm::vec3 dir{0, 0, 1};      // ray direction (ENU)
        glm::vec3 normal{0, 0, 1};   // the smooth surface's at the hit (ENU)
        float coverage = 1;          // share of the pixel's rays that hit it (silhouettes; else 1 or ignored)
        std::int32_t behind = -1;    // near-far edges: the far terrain's hit in behind_ (its own coverage)
    };
    // The camera's ray through continuous pixel coordinates (u, v) (pixel i spans [i, i + 1)).
    Pixel trace(double u, double v) const;
    // Silhouette pixels, against the sky or far terrain: their coverage, a hit for a pixel
    // whose centre missed, and the far terrain's hit where near terrain stands in front of it.
    void antialias_silhouettes();
    const terrain::HeightGrid& grid_;
    PerspectiveOptions options_;
    glm::dvec3 cam_{0.0};  // camera in (texel-centre col, texel-centre row, height m)
    bool camera_inside_ = false;  // over the grid's box of texel centres
    bool below_terrain_ = false;
    double ground_m_ = 0;
    std::vector<Pixel> pixels_;
    std::vector<Pixel> behind_;  // the far surfaces of near-far edge pixels
    Frame frame_;
    std::unique_ptr<SurfaceMarch> march_;
};

}  // namespace ts::render
