#pragma once
// A coordinate reference system and its transform to/from WGS84 lon/lat, backed by PROJ
// (EPSG database). Geographic WGS84 grids skip PROJ entirely.
#include <memory>
#include <optional>
#include <string>

#include <glm/vec2.hpp>

namespace ts::geo {

class Crs {
public:
    // From "EPSG:32633", a PROJ string or WKT. Throws ts::InputError if PROJ does not know it.
    static std::shared_ptr<const Crs> from_definition(const std::string& definition);
    static std::shared_ptr<const Crs> from_epsg(int code);
    // As from_definition, but named `fallback_name` when PROJ has no name for it (a bare PROJ
    // string is "unknown"; a GeoTIFF's citation key says more).
    static std::shared_ptr<const Crs> from_definition(const std::string& definition, const std::string& fallback_name);
    static std::shared_ptr<const Crs> wgs84() { return from_epsg(4326); }

    ~Crs();
    Crs(const Crs&) = delete;
    Crs& operator=(const Crs&) = delete;

    std::optional<int> epsg() const;      // EPSG code if the CRS is one
    const std::string& name() const;      // e.g. "WGS 84 / UTM zone 33N"
    const std::string& definition() const;  // what it was made from
    bool is_geographic() const;

    // CRS coordinates (easting/northing, or lon/lat degrees for geographic CRSs) <-> WGS84 lon/lat.
    // Thread-safe.
    glm::dvec2 to_lonlat(glm::dvec2 xy) const;
    glm::dvec2 from_lonlat(glm::dvec2 lonlat) const;

    // Same CRS (same EPSG code, or PROJ finds the definitions equivalent): mosaics need it.
    bool same_as(const Crs& other) const;
    // PROJ string / WKT1 (GDAL flavour) of the CRS, for writers and messages.
    std::string to_proj_string() const;
    std::string to_wkt() const;

    struct Impl;

private:
    explicit Crs(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// A unit of length: its name and metres per unit.
struct LinearUnit {
    std::string name;
    double metres = 1.0;
};
// The unit of the height axis of EPSG vertical CRS `code` (EPSG:6360, NAVD88 height (ftUS): US
// survey foot), or of EPSG unit of measure `code` (9002: foot); nullopt if PROJ's database does
// not know it as such.
std::optional<LinearUnit> vertical_crs_unit(int code);
std::optional<LinearUnit> linear_unit(int code);

}  // namespace ts::geo
