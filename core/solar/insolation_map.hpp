#pragma once
// An insolation map of a grid: each texel's horizons (D azimuths, interpolated linearly to the
// model's azimuth bins), normal, latitude and height through InsolationModel::texel.
#include <cstdint>
#include <span>
#include <vector>

#include "core/geo/georef.hpp"
#include "core/solar/insolation_model.hpp"
#include "core/terrain/height_grid.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "core/visibility/horizon_set.hpp"

namespace ts {
class ProgressBar;
}

namespace ts::solar {

// [period][quantity][texel] (band-sequential, as the GeoTIFF's bands), NaN where the horizons
// are (void texels).
struct InsolationMap {
    int width = 0, height = 0, periods = 0;
    std::vector<float> values;
    // Per texel: the tilted sky view factor the sums used (NaN on voids), for the second pass
    // (terrain_reflection.hpp).
    std::vector<float> svf;
    const float* band(int period, int quantity) const {
        return values.data() + (std::size_t(period) * kQuantities + std::size_t(quantity)) * std::size_t(width) * height;
    }
};

// Latitude (degrees) of every texel centre: exact every 8 texels and bilinear between (the
// band spacing is far coarser than the error). Throws ts::InputError when the CRS has no
// lon/lat (a local engineering CRS).
std::vector<float> texel_latitudes(const geo::Georef& georef, int threads);

// horizons cover the whole grid; normals and latitudes are per texel.
InsolationMap integrate_insolation(const InsolationModel& model, const terrain::HeightGrid& grid,
                                   const visibility::HorizonSet& horizons, const render::NormalField& normals,
                                   std::span<const float> latitude_deg, ProgressBar* progress = nullptr);

// Rows [row0, row0 + rows) of a map as a map of their own (its svf too).
InsolationMap map_rows(const InsolationMap& map, int row0, int rows);

// The horizons of one texel at the model's bins from its D horizon planes (linear in azimuth).
void bin_horizons(const visibility::HorizonSet& horizons, std::size_t texel, int bins, float* out);

}  // namespace ts::solar
