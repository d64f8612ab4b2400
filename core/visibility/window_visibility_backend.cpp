#include "core/visibility/window_visibility_backend.hpp"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <limits>
#include <memory>

#include "core/util/error.hpp"
#include "core/visibility/compute_horizons.hpp"

namespace ts::visibility {
namespace {

// A core inside its window, both of at least one texel.
void check_rectangles(const ReceiverWindow& window, const ReceiverWindow& core) {
    if (window.width < 1 || window.height < 1 || core.width < 1 || core.height < 1 || window.col0 < 0 ||
        window.row0 < 0 || core.col0 < window.col0 || core.row0 < window.row0 ||
        core.col0 + core.width > window.col0 + window.width || core.row0 + core.height > window.row0 + window.height)
        throw InputError("window visibility: the core must lie inside its window");
}

void check_far_grid(const FarField& far, const ReceiverWindow& window) {
    if (window.col0 + window.width > far.width() || window.row0 + window.height > far.height())
        throw InputError("window visibility: the window lies outside the far field's grid");
}

void check_window_grid(const terrain::HeightGrid& g, const ReceiverWindow& window) {
    if (g.width != window.width || g.height != window.height)
        throw InputError("window visibility: the grid is not the window's");
}

}  // namespace

WindowFarFieldVisibility::WindowFarFieldVisibility(const ReceiverWindow& window, const ReceiverWindow& core,
                                                   const FarField& far)
    : window_(window), core_(core), far_(&far) {
    check_rectangles(window, core);
    check_far_grid(far, window);
}

WindowFarFieldVisibility::WindowFarFieldVisibility(const ReceiverWindow& window, const ReceiverWindow& core,
                                                   const terrain::HeightGrid& grid)
    : window_(window), core_(core), grid_(&grid) {
    check_rectangles(window, core);
    if (window.col0 + window.width > grid.width || window.row0 + window.height > grid.height)
        throw InputError("window visibility: the window lies outside the grid");
}

VisibilityResult WindowFarFieldVisibility::compute(const terrain::HeightGrid& window_grid,
                                                   const VisibilityRequest& request) {
    VisibilityRequest r = request;
    if (!far_) {
        r.horizon.window = window_;
        return cpu_->compute(*grid_, r);
    }
    check_window_grid(window_grid, window_);
    check_request(r);
    // Only the core's receivers: the halo's values are never kept.
    r.horizon.window = {core_.col0 - window_.col0, core_.row0 - window_.row0, core_.width, core_.height};
    VisibilityResult result;
    result.horizons = compute_horizons(window_grid, r.horizon);
    far_->raise(result.horizons, core_, core_, window_grid, {window_.col0, window_.row0});
    grow_to_window(result.horizons);
    r.horizon.window = {};
    result.stages.push_back({"horizons (exact in the window, far field beyond)", "cpu", 0.0});
    complete_on_cpu(window_grid, r, result);
    return result;
}

// The core's horizon set as the window's, the halo's receivers void (NaN), in place: every value
// moves to an offset at or past its own, so copying from the end never overwrites one not yet
// moved.
void WindowFarFieldVisibility::grow_to_window(HorizonSet& set) const {
    const std::size_t cw = std::size_t(core_.width), ch = std::size_t(core_.height);
    const std::size_t ww = std::size_t(window_.width), wn = ww * std::size_t(window_.height), cn = cw * ch;
    const std::size_t dc = std::size_t(core_.col0 - window_.col0), dr = std::size_t(core_.row0 - window_.row0);
    const std::size_t planes = std::size_t(set.directions);
    set.angle.resize(planes * wn);
    float* a = set.angle.data();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (std::size_t d = planes; d-- > 0;) {
        float* to = a + d * wn;
        for (std::size_t r = ch; r-- > 0;) {
            float* row = to + (dr + r) * ww;
            std::memmove(row + dc, a + d * cn + r * cw, cw * sizeof(float));
        }
    }
    // The halo: every window texel outside the core, in every plane.
    for (std::size_t d = 0; d < planes; ++d) {
        float* to = a + d * wn;
        for (std::size_t r = 0; r < std::size_t(window_.height); ++r) {
            float* row = to + r * ww;
            if (r < dr || r >= dr + ch) {
                std::fill(row, row + ww, nan);
            } else {
                std::fill(row, row + dc, nan);
                std::fill(row + dc + cw, row + ww, nan);
            }
        }
    }
    set.width = window_.width, set.height = window_.height;
}

std::unique_ptr<WindowFarFieldVisibility> make_window_far_field_visibility(const ReceiverWindow& window,
                                                                           const ReceiverWindow& core,
                                                                           const FarField& far) {
    return std::make_unique<WindowFarFieldVisibility>(window, core, far);
}

FarFieldSunShadow::FarFieldSunShadow(const ReceiverWindow& window, const ReceiverWindow& core, const FarField& far,
                                     const terrain::HeightGrid& window_grid, double sun_radius_rad)
    : window_(window), core_(core), far_(&far), window_grid_(window_grid), sun_radius_rad_(sun_radius_rad) {
    check_rectangles(window, core);
    check_far_grid(far, window);
    check_window_grid(window_grid, window);
}

void FarFieldSunShadow::operator()(double azimuth_deg, double elevation_deg, std::vector<float>& vis) const {
    if (vis.size() != std::size_t(window_.width) * std::size_t(window_.height))
        throw InputError("window sun shadow: the visibility is not the window's");
    far_->limit_sun(azimuth_deg, elevation_deg, sun_radius_rad_, window_, core_, window_grid_,
                    {window_.col0, window_.row0}, vis.data());
}

}  // namespace ts::visibility
