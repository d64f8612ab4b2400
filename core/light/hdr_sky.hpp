#pragma once
// An equirectangular (latitude-longitude) HDR environment map as a sky.
// Orientation: row 0 is the zenith, the last row the nadir, elevation linear in the row
// (pixel centres at (row + 0.5) / height x 180 degrees from the zenith). Columns run clockwise
// seen from above (left to right = north -> east -> south -> west when the centre faces north),
// the usual panorama convention of a viewer standing inside the sphere; the centre column
// (u = 0.5) faces azimuth `rotation_deg` (clockwise from north), so by default the centre is
// north and the left and right edges south. Pixel values times `scale` are the radiance;
// bilinear lookup, wrapping in azimuth and clamped at the poles.
// The sun stays in the pixels (if the map has one): sun().irradiance is 0 and the direction is
// the one given, used only for the sun's visibility.
#include <glm/vec2.hpp>
#include <mutex>

#include "core/light/sky.hpp"
#include "core/raster/image_io_plugin/float_image_io.hpp"

namespace ts::light {

class HdrSky final : public Sky {
public:
    HdrSky(raster::FloatImage image, std::string source, double rotation_deg, double scale,
           const glm::dvec3& sun_direction_enu);

    Rgb radiance(const glm::dvec3& dir) const override;
    SunDisc sun() const override { return sun_; }
    std::string describe() const override;
    // A pixel: a sun in the map is a pixel or a few.
    double lighting_detail_rad() const override;

    int width() const { return image_.width; }
    int height() const { return image_.height; }
    // The map's pixel column/row coordinates (continuous, pixel centres at .5) of a direction.
    glm::dvec2 map_coordinates(const glm::dvec3& dir) const;
    // Direction (ENU) of the centre of the map's brightest pixel (by luminance): where its sun
    // is, if it has one. The sun stays in the pixels either way.
    glm::dvec3 brightest_direction() const;
    // project_sky_sh of this map with default_sky_rule, computed on first use (thread-safe).
    const SkySh& cached_sh() const;
    // project_diffuse_sky_sh of this map, likewise.
    const SkySh& cached_diffuse_sh() const;

private:
    raster::FloatImage image_;
    std::string source_;
    double rotation_deg_;
    double scale_;
    SunDisc sun_;
    mutable std::once_flag sh_once_;
    mutable SkySh sh_{};
    mutable std::once_flag diffuse_sh_once_;
    mutable SkySh diffuse_sh_{};
};

}  // namespace ts::light
