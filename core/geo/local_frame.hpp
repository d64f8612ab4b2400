#pragma once
// A local east-north-up frame in metres around an origin on the WGS84 ellipsoid
// (GeographicLib::LocalCartesian: exact geodetic <-> ECEF <-> ENU, no flat-earth approximation).
#include <glm/vec3.hpp>

#include <GeographicLib/LocalCartesian.hpp>

namespace ts::geo {

class Georef;

class LocalFrame {
public:
    // origin = {lon, lat, height}: degrees on WGS84, metres above the ellipsoid.
    explicit LocalFrame(glm::dvec3 origin_lonlat_h);

    const glm::dvec3& origin() const { return origin_; }
    // {lon, lat, h} -> {east, north, up} metres. Thread-safe (const GeographicLib calls).
    glm::dvec3 to_enu(glm::dvec3 lonlat_h) const;
    // {east, north, up} metres -> {lon, lat, h}.
    glm::dvec3 to_lonlat_h(glm::dvec3 enu) const;

    // ENU of a raster point: pixel edge coordinates (col, row) and a height above the same
    // surface as the origin's height.
    glm::dvec3 pixel_to_enu(const Georef& georef, double col, double row, double h) const;

    // A frame centred on the raster, at height h.
    static LocalFrame at_raster_centre(const Georef& georef, double h = 0.0);

private:
    glm::dvec3 origin_;
    GeographicLib::LocalCartesian cartesian_;
};

}  // namespace ts::geo
