#include "core/material/material_sources.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/dem/read_dem.hpp"
#include "core/raster/geotiff_georef.hpp"
#include "core/raster/srgb.hpp"
#include "core/raster/tiff_file.hpp"
#include "core/util/error.hpp"

namespace ts::render {

std::vector<glm::dvec2> map_grid_to_source(const geo::Georef& grid, const geo::Georef& source) {
    std::vector<glm::dvec2> out(std::size_t(grid.width()) * std::size_t(grid.height()));
    const bool same = grid.crs().same_as(source.crs());
    for (int r = 0; r < grid.height(); ++r)
        for (int c = 0; c < grid.width(); ++c) {
            const glm::dvec2 xy = grid.pixel_to_crs(c + 0.5, r + 0.5);
            out[std::size_t(r) * std::size_t(grid.width()) + std::size_t(c)] =
                same ? source.crs_to_pixel(xy) : source.lonlat_to_pixel(grid.crs().to_lonlat(xy));
        }
    return out;
}

std::vector<std::uint8_t> read_landcover_on_grid(const std::filesystem::path& path, const geo::Georef& grid) {
    const dem::Dem cover = dem::read_geotiff(path);  // one band of class codes, nodata -> NaN
    const auto where = map_grid_to_source(grid, cover.georef);
    std::vector<std::uint8_t> codes(where.size(), 0);
    std::size_t inside = 0, foreign = 0;
    float example = 0;
    // ESA WorldCover's classes (0: no data). Anything else means the file is no land cover (a DEM
    // given by mistake: its heights would be taken as classes, without a word).
    const auto is_class = [](float v) {
        for (int c : {0, 10, 20, 30, 40, 50, 60, 70, 80, 90, 95, 100})
            if (v == float(c)) return true;
        return false;
    };
    for (std::size_t i = 0; i < where.size(); ++i) {
        const double x = std::floor(where[i].x), y = std::floor(where[i].y);
        if (!(x >= 0 && y >= 0 && x < cover.width && y < cover.height)) continue;
        const float v = cover.at(int(x), int(y));
        if (std::isnan(v)) continue;
        if (!is_class(v)) {
            if (foreign++ == 0) example = v;
            continue;
        }
        codes[i] = std::uint8_t(std::lround(v));
        ++inside;
    }
    if (foreign * 100 > inside + foreign)
        throw input_error(path.string(), "holds values that are no ESA WorldCover class (e.g. " +
                                              std::to_string(example) + "): a land cover holds class codes 10..100 "
                                              "(a DEM given as one?)");
    if (inside == 0) throw input_error(path.string(), "land cover does not overlap the DEM");
    return codes;
}

std::vector<glm::vec3> read_orthophoto_albedo(const std::filesystem::path& path, const geo::Georef& grid) {
    const std::string shown = path.string();
    raster::TiffFile file(path, "r");
    TIFF* tif = file.get();
    std::uint32_t w = 0, h = 0;
    std::uint16_t bits = 8, spp = 1;
    TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &w);
    TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &h);
    TIFFGetFieldDefaulted(tif, TIFFTAG_BITSPERSAMPLE, &bits);
    TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLESPERPIXEL, &spp);
    if (w == 0 || h == 0) throw input_error(shown, "TIFF image of size 0");
    if (bits != 8 || spp < 3)
        throw input_error(shown, "orthophoto must be 8-bit RGB (has " + std::to_string(spp) + " x " +
                                     std::to_string(bits) + "-bit samples)");
    if (std::uint64_t(w) * h > (std::uint64_t(1) << 28)) throw input_error(shown, "orthophoto too large");
    const geo::Georef geo = raster::read_geotiff_georef(tif, int(w), int(h), shown).georef;
    // libtiff's RGBA interface decodes every layout (strips, tiles, planar, JPEG) to ABGR words.
    std::vector<std::uint32_t> pixels(std::size_t(w) * h);
    if (!TIFFReadRGBAImageOriented(tif, w, h, pixels.data(), ORIENTATION_TOPLEFT, 0))
        throw input_error(shown, "cannot decode the orthophoto" +
                                     (file.last_error().empty() ? std::string() : " (" + file.last_error() + ")"));
    float lut[256];
    for (int i = 0; i < 256; ++i) lut[i] = raster::srgb_eotf(float(i) / 255.0f);
    auto texel = [&](int x, int y) {
        const std::uint32_t p = pixels[std::size_t(y) * w + std::size_t(x)];
        return glm::vec3(lut[TIFFGetR(p)], lut[TIFFGetG(p)], lut[TIFFGetB(p)]);
    };
    const auto where = map_grid_to_source(grid, geo);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<glm::vec3> albedo(where.size(), glm::vec3(nan));
    std::size_t inside = 0;
    for (std::size_t i = 0; i < where.size(); ++i) {
        // Edge coordinates -> pixel-centre coordinates for bilinear weights.
        const double x = where[i].x - 0.5, y = where[i].y - 0.5;
        if (!(x >= -0.5 && y >= -0.5 && x <= w - 0.5 && y <= h - 0.5)) continue;
        const int x0 = std::clamp(int(std::floor(x)), 0, int(w) - 1), y0 = std::clamp(int(std::floor(y)), 0, int(h) - 1);
        const int x1 = std::min(x0 + 1, int(w) - 1), y1 = std::min(y0 + 1, int(h) - 1);
        const float fx = float(std::clamp(x - x0, 0.0, 1.0)), fy = float(std::clamp(y - y0, 0.0, 1.0));
        const glm::vec3 top = texel(x0, y0) * (1 - fx) + texel(x1, y0) * fx;
        const glm::vec3 bottom = texel(x0, y1) * (1 - fx) + texel(x1, y1) * fx;
        albedo[i] = top * (1 - fy) + bottom * fy;
        ++inside;
    }
    if (inside == 0) throw input_error(shown, "orthophoto does not overlap the DEM");
    return albedo;
}

}  // namespace ts::render
