#pragma once
// Everything `render`, `relight` and `bench relight` share: a DEM turned once into normals,
// materials, visibility and transfer vectors (and camera rays for a perspective view), then
// frames for any number of sun positions and skies.
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
#include "core/render/perspective_view.hpp"
#include "core/render/sky_table.hpp"
#include "core/render/tone_map.hpp"
#include "core/terrain/height_grid.hpp"

namespace ts::render {

enum class ViewKind { map, perspective };

struct SceneOptions {
    std::string materials = "rule";  // "rule" or a WorldCover GeoTIFF
    std::string albedo;              // RGB orthophoto GeoTIFF, or empty
    MaterialRule rule;
    RendererOptions renderer;
    light::SkyOptions sky;
    ViewKind view = ViewKind::map;
    std::optional<Camera> camera;    // perspective; default_camera() if empty
    PerspectiveOptions perspective;
    // Map: output size (0 = the DEM grid); the texels are resampled bilinearly.
    int map_width = 0, map_height = 0;
};

// A linear RGB picture (the sky's units).
struct LinearImage {
    int width = 0, height = 0;
    std::vector<glm::vec3> rgb;
};

class Scene {
public:
    // The Dem (voids filled, void_mask kept) must outlive the scene.
    Scene(const dem::Dem& dem, const SceneOptions& options);

    // Sun position at the DEM's centre (lon/lat from its georef, its mean height) at `time`.
    SunState sun_at(light::UtcTime time) const;

    // Renders one frame: the sky from options.sky for this sun, per-texel radiance, then the
    // view. `image` keeps its storage from frame to frame.
    void render(const SunState& sun, LinearImage& image);
    // The sky of the last frame (for its description).
    const light::Sky* last_sky() const { return sky_.get(); }

    const FrameRenderer& renderer() const { return *renderer_; }
    FrameRenderer& renderer() { return *renderer_; }
    const terrain::HeightGrid& grid() const { return *grid_; }
    const Camera* camera() const { return camera_ ? &*camera_ : nullptr; }
    // The per-texel radiance of the last frame of a perspective view or a resampled map (a map on
    // the DEM grid is rendered straight into the image: there it is the image's rgb).
    const std::vector<glm::vec3>& texel_radiance() const { return texel_radiance_; }
    const SceneOptions& options() const { return options_; }

private:
    const dem::Dem& dem_;
    SceneOptions options_;
    std::unique_ptr<terrain::HeightGrid> grid_;
    std::unique_ptr<FrameRenderer> renderer_;
    std::optional<Camera> camera_;
    std::unique_ptr<PerspectiveView> perspective_;
    std::unique_ptr<light::Sky> sky_;
    SkyTable sky_table_{256, 128};
    std::vector<glm::vec3> texel_radiance_;
};

// Writes a picture by extension: .png / .tif / .tiff (8-bit sRGB after exposure and the
// filmic curve; a .tif of a map view is georeferenced with `georef`), .exr (linear, no tone
// mapping). Atomic. Returns the exposure scale used (1 for EXR).
double write_image(const std::string& path, const LinearImage& image, const Exposure& exposure,
                   const geo::Georef* georef);
// The exposure scale an image gets (auto: from its log-average luminance).
double image_exposure_scale(const LinearImage& image, const Exposure& exposure);
// Checks the extension before any work; throws ts::InputError naming the path.
void check_image_extension(const std::string& path);

}  // namespace ts::render
