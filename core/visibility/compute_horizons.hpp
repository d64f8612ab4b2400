#pragma once
// Horizon angles per receiver texel and azimuth, by the method the options name.
#include "core/terrain/height_grid.hpp"
#include "core/visibility/horizon_options.hpp"
#include "core/visibility/horizon_set.hpp"

namespace ts::visibility {

// Throws ts::InputError for an empty grid, a bad window or absurd options.
HorizonSet compute_horizons(const terrain::HeightGrid& grid, const HorizonOptions& options);

// The individual methods (same contract; `window` already resolved to the grid).
HorizonSet exact_horizons(const terrain::HeightGrid& grid, const HorizonOptions& options);
HorizonSet raymarch_horizons(const terrain::HeightGrid& grid, const HorizonOptions& options);
HorizonSet pyramid_horizons(const terrain::HeightGrid& grid, const HorizonOptions& options);

// The window with -1 sizes replaced; throws if it does not fit in the grid.
ReceiverWindow resolve_window(const terrain::HeightGrid& grid, const ReceiverWindow& window);

}  // namespace ts::visibility
