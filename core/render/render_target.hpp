#pragma once
// Where a frame's per-texel radiance (on the DEM grid) becomes a picture. Three kinds:
//   GridTarget     the DEM grid itself, or resampled to another size (a map)
//   ExtentTarget   any georeferenced extent in any CRS at any size (one Web Mercator map tile
//                  is one): each pixel centre is carried to the DEM's pixel coordinates once,
//                  then every frame samples the radiance there (bilinear); pixels off the DEM
//                  or outside its terrain, or over a filled hole (terrain::unmeasured_mask), are transparent
//   CameraTarget   a perspective camera (perspective_view.hpp), with the sky where rays miss
// Map-like targets look from straight up (one ViewShading serves them all); a camera has a
// direction per texel. A map whose pixels are smaller than the texels shades the sun per pixel
// (map_pixel_sun.hpp), as a camera does.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "core/dem/dem.hpp"
#include "core/geo/georef.hpp"
#include "core/light/sky.hpp"
#include "core/render/map_pixel_sun.hpp"
#include "core/render/perspective_view.hpp"
#include "core/light/sky_table.hpp"
#include "core/render/view_shading.hpp"

namespace ts::render {

// A linear RGB picture (the sky's units), with coverage where the target has some.
struct LinearImage {
    int width = 0, height = 0;
    std::vector<glm::vec3> rgb;
    std::vector<std::uint8_t> alpha;  // 255 covered, 0 transparent; empty = all covered
};

class RenderTarget {
public:
    virtual ~RenderTarget() = default;
    virtual int width() const = 0;
    virtual int height() const = 0;
    // Towards the viewer, per DEM texel (map-like targets: straight up).
    virtual ViewDirections view_directions() const { return {}; }
    // The picture's georeferencing (map-like targets), or nullptr (a camera).
    virtual const geo::Georef* georef() const { return nullptr; }
    // True when the picture is the texel raster itself (the frame renders straight into it).
    virtual bool is_texel_grid() const { return false; }
    // The picture from one frame's per-texel radiance and its sky. `sun_term` (may be null) is
    // the radiance's diffuse sun term for targets that shade it per pixel (a camera).
    virtual void compose(const std::vector<glm::vec3>& texel_radiance, const TexelSunTerm* sun_term,
                         const light::Sky& sky, LinearImage& image) = 0;
    // Map targets whose pixels are smaller than the texels: shade the sun per pixel from now on
    // (map_pixel_sun.hpp; `grid` outlives the target). Nothing for other targets.
    virtual void shade_sun_per_pixel(const terrain::HeightGrid& /*grid*/, bool /*pixel_shadows*/, double /*curvature*/,
                                     int /*threads*/) {}
    // Whether compose() shades the sun per pixel when given the frame's sun term.
    virtual bool shades_sun_per_pixel() const { return false; }
};

class GridTarget final : public RenderTarget {
public:
    // The DEM grid resampled to width x height (0 = the grid's own size), bilinear with texel
    // centres aligned as GDAL's -ts; the georef scaled to match. `outside` (one byte per texel,
    // terrain::unmeasured_mask; empty = none) makes those texels transparent: the picture then has
    // an alpha channel, and without outside texels it has none (the bytes as they always were).
    GridTarget(const geo::Georef& dem_georef, int width = 0, int height = 0, std::vector<std::uint8_t> outside = {});
    int width() const override { return georef_.width(); }
    int height() const override { return georef_.height(); }
    const geo::Georef* georef() const override { return &georef_; }
    bool is_texel_grid() const override { return same_size_; }
    void compose(const std::vector<glm::vec3>& texel_radiance, const TexelSunTerm* sun_term, const light::Sky& sky,
                 LinearImage& image) override;
    // On a picture that is the texel grid itself (rendered straight into it): outside texels
    // transparent and black. Nothing when there are none.
    void mark_outside(LinearImage& image) const;
    // When the picture is larger than the grid (either axis).
    void shade_sun_per_pixel(const terrain::HeightGrid& grid, bool pixel_shadows, double curvature, int threads) override;
    bool shades_sun_per_pixel() const override { return pixel_sun_ != nullptr; }

private:
    // Pixel (i, j)'s centre in texel-centre coordinates.
    double texel_x(int i) const { return (i + 0.5) * grid_width_ / georef_.width() - 0.5; }
    double texel_y(int j) const { return (j + 0.5) * grid_height_ / georef_.height() - 0.5; }
    int grid_width_, grid_height_;
    geo::Georef georef_;
    bool same_size_;
    std::vector<std::uint8_t> outside_;
    std::unique_ptr<MapPixelSun> pixel_sun_;
    std::vector<std::uint8_t> shaded_;  // per frame: the pixels pixel_sun_ shaded
};

class ExtentTarget final : public RenderTarget {
public:
    // `target` in any CRS PROJ knows; `dem` gives the texel raster's georef and voids.
    ExtentTarget(const dem::Dem& dem, const geo::Georef& target, int threads = 0);
    int width() const override { return georef_.width(); }
    int height() const override { return georef_.height(); }
    const geo::Georef* georef() const override { return &georef_; }
    void compose(const std::vector<glm::vec3>& texel_radiance, const TexelSunTerm* sun_term, const light::Sky& sky,
                 LinearImage& image) override;
    // Pixels that show the DEM.
    std::size_t covered_pixels() const { return covered_; }
    // When the pixels are smaller than the texels (mean step along rows or columns).
    void shade_sun_per_pixel(const terrain::HeightGrid& grid, bool pixel_shadows, double curvature, int threads) override;
    bool shades_sun_per_pixel() const override { return pixel_sun_ != nullptr; }

private:
    int grid_width_, grid_height_;
    geo::Georef georef_;
    int threads_;
    // Per pixel: the DEM position in texel-centre coordinates (x < 0: transparent).
    std::vector<glm::vec2> at_;
    std::size_t covered_ = 0;
    std::unique_ptr<MapPixelSun> pixel_sun_;
    std::vector<std::uint8_t> shaded_;  // per frame: the pixels pixel_sun_ shaded
};

class CameraTarget final : public RenderTarget {
public:
    CameraTarget(const terrain::HeightGrid& grid, const geo::Georef& georef, const Camera& camera,
                 const PerspectiveOptions& options);
    int width() const override { return view_.width(); }
    int height() const override { return view_.height(); }
    ViewDirections view_directions() const override;
    void compose(const std::vector<glm::vec3>& texel_radiance, const TexelSunTerm* sun_term, const light::Sky& sky,
                 LinearImage& image) override;
    const PerspectiveView& view() const { return view_; }
    const Camera& camera() const { return camera_; }
    // The sky as the last compose() tabulated it (the haze over meshes drawn into the picture).
    const light::SkyTable& sky_table() const { return sky_table_; }

private:
    Camera camera_;
    PerspectiveView view_;
    light::SkyTable sky_table_{light::SkyGrid::whole_sphere(256, 128)};
};

}  // namespace ts::render
