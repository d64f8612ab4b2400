#include "app/dem_input.hpp"

#include <cstdio>

#include "core/dem/crop.hpp"
#include "core/dem/fill_voids.hpp"
#include "core/dem/mosaic.hpp"
#include "core/dem/read_dem.hpp"
#include "core/dem/statistics.hpp"
#include "core/material/palette_materials.hpp"
#include "core/util/error.hpp"

namespace ts::app {

void add_dem_input_options(CLI::App& cmd, DemInput& in, bool with_fill_option) {
    cmd.add_option("DEM", in.files,
                   "DEM files: SRTM .hgt, .hgt.zip or GeoTIFF; several files on one grid form one mosaic "
                   "(shared edge rows/columns counted once)")
        ->required();
    cmd.add_option("--crop", in.crop, "Keep only the cells overlapping this WGS84 lon/lat box, degrees")
        ->type_name("W,S,E,N")
        ->delimiter(',');
    if (with_fill_option)
        cmd.add_flag("!--no-fill", in.fill_voids,
                     "Leave voids (nodata) as NaN instead of filling them from their rim");
    if (with_fill_option)
        cmd.add_option("--fill-max-distance", in.fill_max_distance,
                       "Fill a hole enclosed by data only if each of its texels is within N texels of a measured one "
                       "(as gdal_fillnodata -md); wider holes and nodata touching the DEM's border stay outside the "
                       "terrain (transparent)")
            ->type_name("N")
            ->capture_default_str();
}

ts::dem::Dem load_dem_input(const DemInput& in) {
    if (in.files.empty()) throw InputError("no DEM file given");
    if (in.fill_max_distance < 0)
        throw InputError("--fill-max-distance must be >= 0 texels (got " + std::to_string(in.fill_max_distance) + ")");
    std::vector<dem::Dem> parts;
    parts.reserve(in.files.size());
    for (const auto& f : in.files) parts.push_back(dem::read_dem(f));
    dem::Dem d = dem::mosaic(std::move(parts));
    if (!in.crop.empty()) {
        if (in.crop.size() != 4) throw InputError("--crop needs W,S,E,N (four numbers)");
        d = dem::crop(d, {in.crop[0], in.crop[1], in.crop[2], in.crop[3]});
    }
    if (in.fill_voids) dem::fill_voids(d, {in.fill_max_distance});
    return d;
}

void warn_if_single_line(const dem::Dem& d) {
    if (d.width >= 2 && d.height >= 2) return;
    std::fprintf(stderr,
                 "terrashade: warning: %s is %dx%d cells: with no neighbours every horizon is open and the ground "
                 "flat\n",
                 d.source.c_str(), d.width, d.height);
}

bool raise_sea_floor_to_surface(dem::Dem& d) {
    const double lowest = dem::height_stats(d).min;  // NaN when all void: no sea floor
    if (!(lowest < render::kSeaFloorBelowM)) return false;
    std::size_t raised = 0;
    for (float& z : d.z)
        if (z < 0.0f) z = 0.0f, ++raised;
    std::fprintf(stderr,
                 "terrashade: note: %s holds the sea floor (down to %.0f m): its %zu texels below 0 m are summed as "
                 "the sea's surface, at 0 m\n",
                 d.source.c_str(), lowest, raised);
    return true;
}

}  // namespace ts::app
