#pragma once
// Horizon elevation angles for a window of receivers and D azimuths.
// Internal azimuth phi_d = 2 pi d / D, counter-clockwise from east
// (../shared/design/ARCHITECTURE.md); user_azimuth_deg() converts to degrees clockwise from
// north, the one place that does.
#include <cmath>
#include <cstddef>
#include <vector>

#include "core/util/angles.hpp"
#include "core/util/uninitialised_vector.hpp"

namespace ts::visibility {

// Where the receivers are: a window of the height grid (the whole grid by default). Blockers
// are always read from the whole grid, so a tile computed alone equals the same texels of the
// whole-grid result.
struct ReceiverWindow {
    int col0 = 0, row0 = 0, width = -1, height = -1;  // width/height -1 = to the grid's edge
};

inline double azimuth_rad(int d, int directions) {
    return 2.0 * kPi * d / directions;
}

// Degrees clockwise from north for internal azimuth index d.
inline double user_azimuth_deg(int d, int directions) {
    double a = 90.0 - 360.0 * d / directions;
    while (a < 0) a += 360.0;
    while (a >= 360.0) a -= 360.0;
    return a;
}

struct HorizonSet {
    int width = 0, height = 0;  // of the receiver window
    int directions = 0;
    // Elevation angle in radians of the highest blocker, [d * width * height + row * width + col].
    // Negative on peaks (curvature, or terrain falling away); 0 where no terrain lies in that
    // direction (receiver on the grid's edge facing out); NaN for void receivers. resize()
    // leaves new planes unwritten (uninitialised_vector.hpp): whoever sizes the set fills it.
    UninitialisedVector<float> angle;

    std::size_t texels() const { return std::size_t(width) * std::size_t(height); }
    float at(int d, int col, int row) const {
        return angle[std::size_t(d) * texels() + std::size_t(row) * width + col];
    }
    float* plane(int d) { return angle.data() + std::size_t(d) * texels(); }
    const float* plane(int d) const { return angle.data() + std::size_t(d) * texels(); }
};

}  // namespace ts::visibility
