// `terrashade hillshade`: the classic Horn hillshade, as gdaldem computes it but with true metric
// spacing per row (geographic DEMs need no -s). The baseline every later chart compares against.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <memory>
#include <string>

#include "app/command.hpp"
#include "app/dem_input.hpp"
#include "core/raster/raster_writer.hpp"
#include "core/render/hillshade.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/util/error.hpp"

namespace ts::app {
namespace {

struct HillshadeArgs {
    DemInput input;
    std::string out;
    render::HillshadeOptions shade;
};

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

void run_hillshade(const HillshadeArgs& args) {
    // Check everything cheap before reading the DEM.
    render::validate(args.shade);
    const std::string ext = lower_extension(args.out);
    if (ext != ".png" && ext != ".tif" && ext != ".tiff") {
        throw input_error(args.out, "unsupported output format '" + ext + "' (use .png or .tif)");
    }
    const dem::Dem dem = load_dem_input(args.input);
    const terrain::HeightGrid grid = terrain::metric_view(dem);
    const std::vector<std::uint8_t> shade = render::hillshade(grid, args.shade);
    raster::write_u8_image(args.out, dem.width, dem.height, 1, shade.data(), &dem.georef, int(render::kHillshadeNodata));
}

}  // namespace

void add_hillshade_command(CLI::App& root) {
    auto args = std::make_shared<HillshadeArgs>();
    CLI::App* cmd = root.add_subcommand(
        "hillshade",
        "Classic local hillshade (Horn gradients), as gdaldem hillshade but with true metric cell sizes per row; "
        "output bytes 1..255, 0 = nodata (voids; the border too with --no-edges)");
    add_dem_input_options(*cmd, args->input);
    cmd->add_option("-o,--out", args->out, "Output image: .png, or .tif for a georeferenced GeoTIFF (written atomically)")
        ->required();
    cmd->add_option("--azimuth", args->shade.azimuth_deg, "Light azimuth, degrees clockwise from north")
        ->capture_default_str();
    cmd->add_option("--altitude", args->shade.altitude_deg, "Light altitude above the horizon, degrees in [0, 90]")
        ->capture_default_str();
    cmd->add_option("-z,--z-factor", args->shade.z_factor, "Vertical exaggeration (> 0)")->capture_default_str();
    cmd->add_option("--threads", args->shade.threads, "Worker threads (0 = one per core)")->capture_default_str();
    cmd->add_flag("!--no-edges", args->shade.compute_edges,
                  "Leave the border and the rims of voids unshaded (0), as gdaldem without -compute_edges");
    cmd->callback([args] { run_hillshade(*args); });
}

}  // namespace ts::app
