#pragma once
// What a horizon computation is asked to do; every knob has a default.
#include <string>

#include "core/visibility/horizon_method.hpp"
#include "core/visibility/horizon_set.hpp"

namespace ts {
class ProgressBar;
}

namespace ts::visibility {

struct HorizonOptions {
    int directions = 32;
    HorizonMethod method = HorizonMethod::exact;
    bool curvature = true;  // Earth curvature with standard refraction (earth_curvature.hpp)
    // exact: sweep lines per texel across the sweep direction (1 = one line per texel row or
    // column; 2 halves the lateral interpolation distance at twice the cost).
    int exact_lines_per_texel = 1;
    // exact: how far (in texels) each receiver's near field is marched from the texel centre
    // itself before the sweep's far field takes over (0 = pure sweep, interpolated between lines).
    double exact_near_field_texels = 2.0;
    // exact: sweep the far field 8 lines at a time as AVX-512 lanes where the CPU has it
    // (sweep_lanes.hpp); the horizons are bit-identical either way, off only for comparisons.
    bool exact_simd_lines = true;
    // pyramid: sampling schedule name (horizon_method.hpp: fast, balanced, fine, finest).
    std::string pyramid_schedule = "balanced";
    ReceiverWindow window;
    int threads = 0;  // 0 = one per hardware core
    // Advanced by one per receiver texel and azimuth; may be null.
    ProgressBar* progress = nullptr;
};

}  // namespace ts::visibility
