#include "core/raster/geotiff_georef.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <geo_normalize.h>
#include <geotiff.h>
#include <geovalues.h>
#include <xtiffio.h>

#include "core/util/error.hpp"
#include "core/util/isolated_call.hpp"

namespace ts::raster {

namespace {

constexpr unsigned short kUserDefined = 32767;

bool is_code(unsigned short c) { return c >= 1024 && c < kUserDefined; }

struct GtifHandle {
    GTIF* gt;
    ~GtifHandle() {
        if (gt) GTIFFree(gt);
    }
};

// libgeotiff's complaints (a corrupt key directory) go to the message of the one line we
// print, not to stderr on their own: its first error is kept in the std::string user data.
void keep_geotiff_error(GTIF* gt, int level, const char* format, ...) {
    auto* first = gt ? static_cast<std::string*>(GTIFGetUserData(gt)) : nullptr;
    if (!first || !first->empty() || level != LIBGEOTIFF_ERROR) return;
    char text[512];
    va_list args;
    va_start(args, format);
    std::vsnprintf(text, sizeof text, format, args);
    va_end(args);
    *first = text;
}

std::optional<unsigned short> short_key(GTIF* gt, geokey_t key) {
    unsigned short v = 0;
    if (GTIFKeyGetSHORT(gt, key, &v, 0, 1) == 1) return v;
    return std::nullopt;
}

// The pixel -> CRS affine transform in *raster space* (GeoTIFF's own: (0,0) is the outer
// corner for PixelIsArea, the first pixel's centre for PixelIsPoint).
bool raster_space_transform(TIFF* tif, geo::GeoTransform& t) {
    std::uint16_t count = 0;
    double* values = nullptr;
    if (TIFFGetField(tif, TIFFTAG_GEOTRANSMATRIX, &count, &values) && count >= 16) {
        t.x0 = values[3];
        t.dx_col = values[0];
        t.dx_row = values[1];
        t.y0 = values[7];
        t.dy_col = values[4];
        t.dy_row = values[5];
        return true;
    }
    std::uint16_t n_tie = 0, n_scale = 0;
    double* tie = nullptr;
    double* scale = nullptr;
    if (TIFFGetField(tif, TIFFTAG_GEOTIEPOINTS, &n_tie, &tie) && n_tie >= 6 &&
        TIFFGetField(tif, TIFFTAG_GEOPIXELSCALE, &n_scale, &scale) && n_scale >= 2) {
        // Tiepoint (I, J, K, X, Y, Z): raster (I, J) is model (X, Y); rows go south.
        t.dx_col = scale[0];
        t.dx_row = 0;
        t.dy_col = 0;
        t.dy_row = -scale[1];
        t.x0 = tie[3] - tie[0] * scale[0];
        t.y0 = tie[4] + tie[1] * scale[1];
        return true;
    }
    return false;
}

// User-defined keys assembled into a PROJ string by libgeotiff, in a child process: its
// normalisation writes into fixed buffers (GTIFGetProj4Defn strcat()s names taken from the
// file), so a crafted file overflows them and aborts the process. A crash there becomes an
// InputError. Empty when libgeotiff cannot resolve the keys.
std::string proj_string_from_user_defined_keys(GTIF* gt, const std::string& path) {
    IsolationLimits limits;
    limits.timeout_s = 8.0;
    const std::vector<std::uint8_t> bytes = run_isolated(
        [gt] {
            // Only this child's stderr: libgeotiff and PROJ print their complaints there, and
            // libc its abort message; the caller reports one line.
            if (const int null_fd = ::open("/dev/null", O_WRONLY); null_fd >= 0) ::dup2(null_fd, STDERR_FILENO);
            std::string definition;
            GTIFDefn* defn = GTIFAllocDefn();
            if (GTIFGetDefn(gt, defn) && defn->DefnSet) {
                if (char* proj4 = GTIFGetProj4Defn(defn)) {
                    definition = proj4;
                    GTIFFreeMemory(proj4);
                }
                // libgeotiff reads GeogTOWGS84GeoKey but leaves it out of the PROJ string: without
                // it a local datum's map lies ~100 m off (ED50 in France: 140 m).
                if (!definition.empty() && definition.find("+towgs84") == std::string::npos &&
                    (defn->TOWGS84Count == 3 || defn->TOWGS84Count == 7)) {
                    definition += " +towgs84=";
                    for (int k = 0; k < defn->TOWGS84Count; ++k) {
                        char v[40];
                        std::snprintf(v, sizeof v, "%s%.10g", k ? "," : "", defn->TOWGS84[k]);
                        definition += v;
                    }
                }
            }
            GTIFFreeDefn(defn);
            return std::vector<std::uint8_t>(definition.begin(), definition.end());
        },
        path + " (its user-defined GeoKeys)", limits);
    std::string definition(bytes.begin(), bytes.end());
    // PROJ reads a bare "+proj=..." as a conversion; "+type=crs" makes it a CRS.
    if (!definition.empty() && definition.find("+type=crs") == std::string::npos) definition += " +type=crs";
    return definition;
}

std::string vertical_datum_name(unsigned short code) {
    switch (code) {
        case 5773: return "EGM96 geoid";
        case 3855: return "EGM2008 geoid";
        case 5798: return "EGM84 geoid";
        case 5703: return "NAVD88";
        case 5720: return "NGF-IGN69";
        default: return "EPSG:" + std::to_string(code);
    }
}

std::shared_ptr<const geo::Crs> crs_from_keys(GTIF* gt, const std::string& path) {
    const auto model = short_key(gt, GTModelTypeGeoKey);
    const auto pcs = short_key(gt, ProjectedCSTypeGeoKey);
    const auto gcs = short_key(gt, GeographicTypeGeoKey);
    std::string definition;
    if (model == ModelTypeProjected && pcs && is_code(*pcs)) {
        definition = "EPSG:" + std::to_string(*pcs);
    } else if (model == ModelTypeGeographic && gcs && is_code(*gcs)) {
        definition = "EPSG:" + std::to_string(*gcs);
    } else if (model == ModelTypeProjected || model == ModelTypeGeographic) {
        definition = proj_string_from_user_defined_keys(gt, path);
        if (definition.empty()) throw input_error(path, "unknown coordinate reference system (user-defined GeoKeys libgeotiff cannot resolve)");
    } else if (!model) {
        throw input_error(path, "GeoTIFF without GTModelTypeGeoKey: unknown coordinate reference system");
    } else {
        throw input_error(path, "unsupported GeoTIFF model type " + std::to_string(*model) + " (geocentric?)");
    }
    // The file's own name for a user-defined CRS (GDAL writes it as the citation).
    std::string citation;
    for (geokey_t key : {PCSCitationGeoKey, GTCitationGeoKey, GeogCitationGeoKey}) {
        char text[512] = {};
        if (citation.empty() && GTIFKeyGet(gt, key, text, 0, sizeof text - 1) > 0) citation = text;
    }
    try {
        return geo::Crs::from_definition(definition, citation);
    } catch (const InputError&) {
        throw input_error(path, "unknown coordinate reference system " + definition);
    }
}

}  // namespace

GeoTiffGeoref read_geotiff_georef(TIFF* tif, int width, int height, const std::string& path) {
    geo::GeoTransform raster_space;
    const bool has_transform = raster_space_transform(tif, raster_space);
    std::string geotiff_error;
    GtifHandle gt{GTIFNewEx(tif, keep_geotiff_error, &geotiff_error)};
    std::uint16_t n_keys = 0;
    std::uint16_t* keys = nullptr;
    const bool has_keys = TIFFGetField(tif, TIFFTAG_GEOKEYDIRECTORY, &n_keys, &keys) && n_keys >= 4;
    if (!has_transform && !has_keys)
        throw input_error(path, "TIFF without georeferencing (no GeoTIFF tiepoint, scale or GeoKeys)");
    if (!has_transform) throw input_error(path, "GeoTIFF without ModelTiepoint+ModelPixelScale or ModelTransformation");
    if (has_keys && !gt.gt)
        throw input_error(path, "corrupt GeoKeys (" + (geotiff_error.empty() ? std::string("unreadable") : geotiff_error) + ")");
    if (!has_keys) throw input_error(path, "GeoTIFF without GeoKeys: unknown coordinate reference system");
    // A zero or non-finite scale maps every cell to one point or to NaN, and every later
    // pixel <-> map conversion (crop, info's corners) with it.
    const geo::GeoTransform& r = raster_space;
    const double det = r.dx_col * r.dy_row - r.dx_row * r.dy_col;
    if (!std::isfinite(r.x0) || !std::isfinite(r.y0) || !std::isfinite(det) || det == 0)
        throw input_error(path, "degenerate GeoTIFF georeferencing (a zero, infinite or NaN pixel scale or transformation)");

    const auto raster_type = short_key(gt.gt, GTRasterTypeGeoKey);
    const bool pixel_is_area = raster_type != RasterPixelIsPoint;
    geo::GeoTransform edge = raster_space;
    if (!pixel_is_area) {
        // Raster-space (0,0) is the first pixel's centre: the outer edge is half a pixel before it.
        const glm::dvec2 corner = raster_space.apply(-0.5, -0.5);
        edge.x0 = corner.x;
        edge.y0 = corner.y;
    }
    GeoTiffGeoref out;
    out.georef = geo::Georef(width, height, edge, crs_from_keys(gt.gt, path), pixel_is_area);
    if (const auto v = short_key(gt.gt, VerticalCSTypeGeoKey); v && is_code(*v)) {
        out.vertical_datum = vertical_datum_name(*v);
        out.vertical_cs_code = *v;
    }
    if (const auto u = short_key(gt.gt, VerticalUnitsGeoKey); u && is_code(*u)) out.vertical_units_code = *u;
    return out;
}

void write_geotiff_georef(TIFF* tif, const geo::Georef& georef, const std::string& path) {
    const geo::GeoTransform& t = georef.transform();
    const bool pixel_is_area = georef.pixel_is_area();
    // Written in the file's own raster type so a PixelIsPoint source round-trips as such.
    const glm::dvec2 origin = pixel_is_area ? t.apply(0, 0) : t.apply(0.5, 0.5);
    if (t.dx_row == 0 && t.dy_col == 0 && t.dy_row < 0) {
        double tie[6] = {0, 0, 0, origin.x, origin.y, 0};
        double scale[3] = {t.dx_col, -t.dy_row, 0};
        TIFFSetField(tif, TIFFTAG_GEOTIEPOINTS, 6, tie);
        TIFFSetField(tif, TIFFTAG_GEOPIXELSCALE, 3, scale);
    } else {
        double m[16] = {t.dx_col, t.dx_row, 0, origin.x, t.dy_col, t.dy_row, 0, origin.y, 0, 0, 0, 0, 0, 0, 0, 1};
        TIFFSetField(tif, TIFFTAG_GEOTRANSMATRIX, 16, m);
    }

    GtifHandle gt{GTIFNew(tif)};
    if (!gt.gt) throw input_error(path, "cannot write GeoTIFF keys");
    const geo::Crs& crs = georef.crs();
    const auto code = crs.epsg();
    if (code && *code > 0 && *code < kUserDefined) {
        const bool geographic = crs.is_geographic();
        GTIFKeySet(gt.gt, GTModelTypeGeoKey, TYPE_SHORT, 1, geographic ? ModelTypeGeographic : ModelTypeProjected);
        GTIFKeySet(gt.gt, geographic ? GeographicTypeGeoKey : ProjectedCSTypeGeoKey, TYPE_SHORT, 1, *code);
        GTIFKeySet(gt.gt, GTCitationGeoKey, TYPE_ASCII, 0, crs.name().c_str());
    } else {
        const std::string proj = crs.to_proj_string();
        if (!GTIFSetFromProj4(gt.gt, proj.c_str()))
            throw input_error(path, "cannot express the CRS '" + crs.name() + "' as GeoTIFF keys");
        // GTIFSetFromProj4 drops the datum shift, as GTIFGetProj4Defn does on reading.
        if (const auto at = proj.find("+towgs84="); at != std::string::npos) {
            std::vector<double> shift;
            const char* p = proj.c_str() + at + 9;
            for (char* end = nullptr;; p = end + 1) {
                const double v = std::strtod(p, &end);
                if (end == p) break;
                shift.push_back(v);
                if (*end != ',') break;
            }
            if (shift.size() == 3 || shift.size() == 7)
                GTIFKeySet(gt.gt, GeogTOWGS84GeoKey, TYPE_DOUBLE, int(shift.size()), shift.data());
        }
        if (!crs.name().empty() && crs.name() != "unknown")
            GTIFKeySet(gt.gt, GTCitationGeoKey, TYPE_ASCII, 0, crs.name().c_str());
    }
    GTIFKeySet(gt.gt, GTRasterTypeGeoKey, TYPE_SHORT, 1, pixel_is_area ? RasterPixelIsArea : RasterPixelIsPoint);
    GTIFWriteKeys(gt.gt);
}

}  // namespace ts::raster
