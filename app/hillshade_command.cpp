// `terrashade hillshade`: the classic Horn hillshade, as gdaldem computes it but with true metric
// spacing per row (geographic DEMs need no -s). The baseline every later chart compares against.
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "app/command.hpp"
#include "app/options/sun_options.hpp"
#include "app/options/threads_option.hpp"
#include "app/dem_input.hpp"
#include "app/io_plan.hpp"
#include "core/raster/raster_writer.hpp"
#include "core/render/hillshade.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/terrain/outside_terrain.hpp"
#include "core/util/error.hpp"
#include "core/raster/image_writer_registry.hpp"

namespace ts::app {
namespace {

struct HillshadeArgs {
    DemInput input;
    std::string out;
    render::HillshadeOptions shade;
};

void run_hillshade(const HillshadeArgs& args) {
    // Check everything cheap before reading the DEM.
    render::validate(args.shade);
    IoPlan plan;
    plan.inputs("DEM", args.input.files).output("--out", args.out, raster::u8_picture_extensions());
    plan.check();
    const dem::Dem dem = load_dem_input(args.input);
    // A gradient needs two cells along each axis (2x2 with the edges computed; a full 3x3 window
    // with --no-edges): below that every pixel would be nodata.
    const int least = args.shade.compute_edges ? 2 : 3;
    if (dem.width < least || dem.height < least)
        throw input_error(dem.source, "the DEM is " + std::to_string(dem.width) + "x" + std::to_string(dem.height) +
                                          " cells; a hillshade needs at least " + std::to_string(least) + "x" +
                                          std::to_string(least) + (args.shade.compute_edges ? "" : " with --no-edges") +
                                          " (every pixel would be nodata)");
    const terrain::HeightGrid grid = terrain::metric_view(dem);
    const std::vector<std::uint8_t> shade = render::hillshade(grid, args.shade);
    // A PNG of a DEM with texels outside its terrain (a reprojection's collar: docs/terrain.md)
    // is grey + alpha, alpha 0 wherever the value is nodata; without any, one grey band as
    // always. A GeoTIFF keeps one band with nodata 0, as gdaldem writes it (GIS read that as
    // transparent).
    const bool png = raster::written_as(args.out, raster::ImageWriter::png);
    if (!png || terrain::outside_mask(dem.z).empty()) {
        raster::write_u8_image(args.out, dem.width, dem.height, 1, shade.data(), &dem.georef, int(render::kHillshadeNodata));
    } else {
        std::vector<std::uint8_t> grey_alpha(2 * shade.size());
        for (std::size_t k = 0; k < shade.size(); ++k) {
            grey_alpha[2 * k] = shade[k];
            grey_alpha[2 * k + 1] = shade[k] == render::kHillshadeNodata ? 0 : 255;
        }
        raster::write_u8_image(args.out, dem.width, dem.height, 2, grey_alpha.data(), &dem.georef,
                               int(render::kHillshadeNodata));
    }
    std::printf("wrote %s (%dx%d)\n", args.out.c_str(), dem.width, dem.height);
}

}  // namespace

void add_hillshade_command(CLI::App& root) {
    auto args = std::make_shared<HillshadeArgs>();
    CLI::App* cmd = root.add_subcommand(
        "hillshade",
        "Classic local hillshade (Horn gradients), as gdaldem hillshade but with true metric cell sizes per row; "
        "output bytes 1..255, 0 = nodata (voids; the border too with --no-edges); a PNG gets an alpha channel (0 at "
        "nodata) when the DEM has texels outside its terrain, e.g. a reprojection's nodata collar");
    add_dem_input_options(*cmd, args->input);
    cmd->add_option("-o,--out", args->out, "Output image: .png, or .tif for a georeferenced GeoTIFF (written atomically)")
        ->required();
    cmd->add_option("--azimuth", args->shade.azimuth_deg, "Light azimuth, degrees clockwise from north, 0..360")
        ->capture_default_str()
        ->check(azimuth_range());
    cmd->add_option("--altitude", args->shade.altitude_deg, "Light altitude above the horizon, degrees in [0, 90]")
        ->capture_default_str();
    cmd->add_option("-z,--z-factor", args->shade.z_factor, "Vertical exaggeration (> 0)")->capture_default_str();
    add_threads_option(*cmd, args->shade.threads);
    cmd->add_flag("!--no-edges", args->shade.compute_edges,
                  "Leave the border and the rims of voids unshaded (0), as gdaldem without -compute_edges");
    cmd->callback([args] { run_hillshade(*args); });
}

}  // namespace ts::app
