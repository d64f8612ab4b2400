#pragma once
// What every horizon method does around its search, kept in one place so the methods cannot
// drift apart: the output set for the resolved receiver window (0 = no terrain in that
// direction until the search says otherwise), and the conversion of the best slope found to
// the stored angle.
#include <cmath>
#include <cstddef>
#include <limits>

#include "core/visibility/horizon_set.hpp"

namespace ts::visibility {

inline HorizonSet zero_horizons(const ReceiverWindow& win, int directions) {
    HorizonSet out;
    out.width = win.width;
    out.height = win.height;
    out.directions = directions;
    out.angle.assign(out.texels() * std::size_t(directions), 0.0f);
    return out;
}

// The same without writing the planes: for methods that write every texel of every plane
// themselves, from their worker threads.
inline HorizonSet unfilled_horizons(const ReceiverWindow& win, int directions) {
    HorizonSet out;
    out.width = win.width;
    out.height = win.height;
    out.directions = directions;
    out.angle.resize(out.texels() * std::size_t(directions));
    return out;
}

// tan(elevation) of the highest blocker, -infinity if the search met no surface -> radians.
inline float horizon_angle(double best_slope) {
    return best_slope == -std::numeric_limits<double>::infinity() ? 0.0f : float(std::atan(best_slope));
}

}  // namespace ts::visibility
