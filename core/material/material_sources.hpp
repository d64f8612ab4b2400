#pragma once
// Material inputs read from other rasters and put on the DEM's grid by georeferencing: each
// DEM texel centre is carried to the source raster's pixel coordinates (directly when both
// share a CRS, else through WGS84 lon/lat), so the sources may have any CRS and resolution.
// (Namespace ts::render until the renderer's files say material::, docs/architecture.md.)
#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/vec3.hpp>

#include "core/geo/georef.hpp"

namespace ts::render {

// A land-cover GeoTIFF of ESA WorldCover class codes (one 8-bit or integer band), sampled at
// the nearest pixel; 0 outside the raster or on its nodata. Throws ts::InputError
// "path: problem" for an unreadable file, one without georeferencing, or no overlap at all.
std::vector<std::uint8_t> read_landcover_on_grid(const std::filesystem::path& path, const geo::Georef& grid);

// An RGB(A) orthophoto GeoTIFF with 8-bit sRGB-encoded samples, decoded to linear albedo and
// sampled bilinearly; NaN outside the photo (the material keeps its own albedo there).
std::vector<glm::vec3> read_orthophoto_albedo(const std::filesystem::path& path, const geo::Georef& grid);

// Where the centre of each texel of `grid` falls in `source`'s pixel coordinates (edge
// convention, so pixel (i, j) spans [i, i+1) x [j, j+1)). [row * width + col].
std::vector<glm::dvec2> map_grid_to_source(const geo::Georef& grid, const geo::Georef& source);

}  // namespace ts::render
