#pragma once
// GeoTIFF georeferencing <-> geo::Georef: ModelTiepoint + ModelPixelScale or ModelTransformation,
// GTRasterTypeGeoKey (PixelIsPoint files are shifted half a pixel to the edge convention, as
// GDAL does), and the CRS from the GeoKeys (EPSG codes; user-defined keys through libgeotiff's
// GTIFGetDefn + GTIFGetProj4Defn).
#include <string>

#include <tiffio.h>

#include "core/geo/georef.hpp"

namespace ts::raster {

struct GeoTiffGeoref {
    geo::Georef georef;
    // From VerticalCSTypeGeoKey ("EGM96 geoid", "EGM2008 geoid", "EPSG:nnnn"), else "unknown".
    std::string vertical_datum = "unknown";
    // VerticalCSTypeGeoKey and VerticalUnitsGeoKey as the file gives them (0: absent).
    int vertical_cs_code = 0, vertical_units_code = 0;
};

// Throws ts::InputError "path: problem" when the file has no georeferencing or an unknown CRS.
GeoTiffGeoref read_geotiff_georef(TIFF* tif, int width, int height, const std::string& path);

// Writes the tags and GeoKeys for `georef` (EPSG code when the CRS has one, else PROJ string
// through libgeotiff's GTIFSetFromProj4).
void write_geotiff_georef(TIFF* tif, const geo::Georef& georef, const std::string& path);

}  // namespace ts::raster
