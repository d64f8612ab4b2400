#include "core/visibility/compute_horizons.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"

namespace ts::visibility {

ReceiverWindow resolve_window(const terrain::HeightGrid& grid, const ReceiverWindow& window) {
    ReceiverWindow w = window;
    if (w.width < 0) w.width = grid.width - w.col0;
    if (w.height < 0) w.height = grid.height - w.row0;
    if (w.col0 < 0 || w.row0 < 0 || w.width < 1 || w.height < 1 || w.col0 + w.width > grid.width ||
        w.row0 + w.height > grid.height)
        throw InputError("receiver window: does not fit in the " + std::to_string(grid.width) + "x" +
                         std::to_string(grid.height) + " grid");
    return w;
}

HorizonSet compute_horizons(const terrain::HeightGrid& grid, const HorizonOptions& options) {
    if (grid.width < 1 || grid.height < 1 || grid.z.size() != std::size_t(grid.width) * std::size_t(grid.height))
        throw InputError("height grid: empty or inconsistent size");
    if (options.directions < 1 || options.directions > 4096)
        throw QuantityError(Quantity::directions, "", "must be between 1 and 4096, got " + std::to_string(options.directions));
    HorizonSet set;
    switch (options.method) {
        case HorizonMethod::exact:
            set = exact_horizons(grid, options);
            break;
        case HorizonMethod::raymarch:
            set = raymarch_horizons(grid, options);
            break;
        case HorizonMethod::pyramid:
            set = pyramid_horizons(grid, options);
            break;
    }
    // Void receivers get no horizon at all (NaN), whatever the method left there.
    const ReceiverWindow w = resolve_window(grid, options.window);
    for (int r = 0; r < w.height; ++r)
        for (int c = 0; c < w.width; ++c)
            if (std::isnan(grid.at(w.col0 + c, w.row0 + r)))
                for (int d = 0; d < set.directions; ++d)
                    set.plane(d)[std::size_t(r) * w.width + c] = std::numeric_limits<float>::quiet_NaN();
    return set;
}

}  // namespace ts::visibility
