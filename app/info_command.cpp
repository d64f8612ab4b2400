// `terrashade info DEM... [--json]`: what a DEM is, where it lies and what heights it holds.
// Several files are described as the one mosaic every other command would build from them.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include <nlohmann/json.hpp>

#include "app/command.hpp"
#include "app/dem_input.hpp"
#include "app/io_plan.hpp"
#include "core/dem/fill_voids.hpp"
#include "core/dem/statistics.hpp"

namespace ts::app {

namespace {

struct InfoOptions {
    DemInput input;
    bool json = false;
};

struct Corner {
    const char* key;
    const char* label;
    double col_fraction, row_fraction;  // of width/height
};
constexpr Corner kCorners[] = {{"upper_left", "upper left", 0, 0},
                               {"upper_right", "upper right", 1, 0},
                               {"lower_right", "lower right", 1, 1},
                               {"lower_left", "lower left", 0, 1}};

nlohmann::ordered_json number_or_null(double v) { return std::isfinite(v) ? nlohmann::ordered_json(v) : nullptr; }

std::string format(const char* fmt, double a, double b) {
    char buffer[128];
    std::snprintf(buffer, sizeof buffer, fmt, a, b);
    return buffer;
}

void print_json(const dem::Dem& d, const InfoOptions& opts, const dem::HeightStats& s) {
    const geo::Georef& g = d.georef;
    nlohmann::ordered_json j;
    j["files"] = opts.input.files;
    j["width"] = d.width;
    j["height"] = d.height;
    if (auto code = g.crs().epsg()) j["epsg"] = *code;
    else j["epsg"] = nullptr;
    j["crs_name"] = g.crs().name();
    j["crs_is_geographic"] = g.crs().is_geographic();
    j["pixel_is_area"] = g.pixel_is_area();
    nlohmann::ordered_json crs_corners, lonlat_corners;
    for (const Corner& c : kCorners) {
        const double col = c.col_fraction * d.width, row = c.row_fraction * d.height;
        const glm::dvec2 xy = g.pixel_to_crs(col, row);
        const glm::dvec2 ll = g.pixel_to_lonlat(col, row);
        crs_corners[c.key] = {xy.x, xy.y};
        lonlat_corners[c.key] = {ll.x, ll.y};
    }
    j["corners_crs"] = crs_corners;
    j["corners_lonlat"] = lonlat_corners;
    const glm::dvec2 cell = g.cell_size_m();
    j["cell_size_m"] = {cell.x, cell.y};
    j["height_min"] = number_or_null(s.min);
    j["height_max"] = number_or_null(s.max);
    j["height_mean"] = number_or_null(s.mean);
    j["nodata_count"] = s.void_count;
    const dem::VoidKinds kinds = dem::classify_voids(d);  // docs/terrain.md, "Outside the terrain"
    j["nodata_outside_count"] = kinds.outside_texels;
    j["nodata_hole_count"] = kinds.hole_texels;
    j["nodata_holes"] = kinds.holes;
    j["vertical_datum"] = d.vertical_datum;
    j["height_unit"] = d.height_unit;  // as stored; heights are reported in metres
    j["credit"] = d.credit;
    std::cout << j.dump(2) << "\n";
}

void print_text(const dem::Dem& d, const dem::HeightStats& s) {
    const geo::Georef& g = d.georef;
    const geo::Crs& crs = g.crs();
    std::printf("%s\n", d.source.c_str());
    std::printf("  size         %d x %d cells\n", d.width, d.height);
    const auto code = crs.epsg();
    std::printf("  CRS          %s%s (%s)\n", code ? ("EPSG:" + std::to_string(*code) + "  ").c_str() : "no EPSG code  ",
                crs.name().c_str(), crs.is_geographic() ? "geographic, degrees" : "projected, metres");
    std::printf("  raster type  %s\n", g.pixel_is_area() ? "pixel is area (values cover their cell)"
                                                         : "pixel is point (values sampled at cell centres; "
                                                           "corners below are the outer cell edges)");
    const char* crs_fmt = crs.is_geographic() ? "%.8f, %.8f" : "%.3f, %.3f";
    std::printf("  corners      %-30s %s\n", "CRS (x, y)", "WGS84 (lon, lat)");
    for (const Corner& c : kCorners) {
        const double col = c.col_fraction * d.width, row = c.row_fraction * d.height;
        const glm::dvec2 xy = g.pixel_to_crs(col, row);
        const glm::dvec2 ll = g.pixel_to_lonlat(col, row);
        std::printf("   %-11s %-30s %s\n", c.label, format(crs_fmt, xy.x, xy.y).c_str(),
                    format("%.8f, %.8f", ll.x, ll.y).c_str());
    }
    const glm::dvec2 cell = g.cell_size_m();
    std::printf("  cell size    %.3f m east-west x %.3f m north-south (geodesic, at the centre)\n", cell.x, cell.y);
    if (!g.crs().is_geographic())
        std::printf("  true north   %+.4f deg from the grid's north, clockwise, at the centre (meridian convergence; "
                    "sun azimuths are true, turned onto the grid by it)\n",
                    g.grid_azimuth_of_north_deg());
    if (s.valid_count)
        std::printf("  heights      min %.6g m, max %.6g m, mean %.3f m (%s%s)\n", s.min, s.max, s.mean,
                    d.vertical_datum.c_str(),
                    d.height_unit == "metre" ? "" : ("; stored in " + d.height_unit + ", converted").c_str());
    else
        std::printf("  heights      none (every cell is a void)\n");
    if (!d.credit.empty()) std::printf("  credit       %s\n", d.credit.c_str());
    const double total = double(d.width) * double(d.height);
    std::printf("  voids        %zu of %.0f cells (%.3f %%)\n", s.void_count, total, 100.0 * double(s.void_count) / total);
    if (s.void_count && s.valid_count) {
        // Outside: connected to the border, never filled; holes: enclosed by data (docs/terrain.md).
        const dem::VoidKinds k = dem::classify_voids(d);
        std::printf("               %zu outside the terrain (touching the border), %zu in %zu enclosed hole%s\n",
                    k.outside_texels, k.hole_texels, k.holes, k.holes == 1 ? "" : "s");
    }
}

}  // namespace

void add_info_command(CLI::App& root) {
    auto opts = std::make_shared<InfoOptions>();
    opts->input.fill_voids = false;  // describe the heights as measured
    CLI::App* cmd = root.add_subcommand(
        "info",
        "Describe DEM files: size, CRS, pixel-is-area/point, corners in the CRS and in lon/lat, cell size in "
        "metres, height statistics and void count. Several files are described as their mosaic.");
    add_dem_input_options(*cmd, opts->input, /*with_fill_option=*/false);
    cmd->add_flag("--json", opts->json, "Print one JSON object instead of text");
    cmd->callback([opts] {
        IoPlan().inputs("DEM", opts->input.files).check();
        const dem::Dem d = load_dem_input(opts->input);
        const dem::HeightStats s = dem::height_stats(d);
        if (opts->json) print_json(d, *opts, s);
        else print_text(d, s);
    });
}

}  // namespace ts::app
