#pragma once
// A window of a larger grid shaded as a grid of its own: a block of a tile level
// (core/tiles/shade_source.cpp), a detail tile of a DEM streamed by tiles (`fly`). The window is
// a core grown by a halo; the halo is there for the core's normals, its sun shadows and the near
// field of its sky, and the terrain beyond the window comes from a far field
// (far_field_horizons.hpp):
//
//   WindowFarFieldVisibility   horizons (and what derives from them) for the core's receivers
//   FarFieldSunShadow          the sun shadow that terrain beyond the window casts on the core
//
// With a FarField neither reads the larger grid: receiver heights come from the window's own
// grid and the far field keeps only coarse levels, so the larger grid need never be in memory.
//
//   FarField far(coarse, shift, width0, height0, dx0, dy0, z_top, {.start_texels = halo});  // once
//   auto backend = make_window_far_field_visibility(window, core, far);                     // per window
//   options.renderer.visibility = backend.get();
//   options.renderer.outer_sun_shadow = far_field_sun_shadow(window, core, far, window_grid);
//
// Windows and cores are rectangles of the larger grid (in its texels), the core inside the window.
#include <memory>
#include <string>
#include <vector>

#include "core/terrain/height_grid.hpp"
#include "core/visibility/far_field_horizons.hpp"
#include "core/visibility/horizon_set.hpp"
#include "core/visibility/sun_sweep.hpp"
#include "core/visibility/visibility_backend.hpp"

namespace ts::visibility {

class WindowFarFieldVisibility final : public VisibilityBackend {
public:
    // Marched far field: compute() sweeps the window grid it is given exactly, for the core's
    // receivers only, and raises their horizons by `far` (which must outlive the backend); the
    // halo's receivers come back void (NaN), which costs nothing in the products and the transfer.
    WindowFarFieldVisibility(const ReceiverWindow& window, const ReceiverWindow& core, const FarField& far);
    // Exact far field: every receiver of the window swept over every texel of `grid` (the larger
    // grid, which must then be in memory and outlive the backend): the larger grid's own
    // horizons, at a sweep of all of it per window. compute()'s grid is not read.
    WindowFarFieldVisibility(const ReceiverWindow& window, const ReceiverWindow& core, const terrain::HeightGrid& grid);

    std::string name() const override { return cpu_->name(); }
    // `window_grid`: the window's texels as a grid of their own (window.width x window.height).
    VisibilityResult compute(const terrain::HeightGrid& window_grid, const VisibilityRequest& request) override;

private:
    void grow_to_window(HorizonSet& set) const;

    ReceiverWindow window_, core_;
    const FarField* far_ = nullptr;
    const terrain::HeightGrid* grid_ = nullptr;
    std::unique_ptr<VisibilityBackend> cpu_ = make_cpu_visibility_backend();
};

// The marched far field's backend for a window (render::RendererOptions::visibility).
std::unique_ptr<WindowFarFieldVisibility> make_window_far_field_visibility(const ReceiverWindow& window,
                                                                           const ReceiverWindow& core,
                                                                           const FarField& far);

// The far field's limit_sun for the core of a window: a frame's sun visibility of the window
// (row-major, window.width x window.height) lowered where terrain beyond the window hides the
// sun; the halo's texels are left as they are. Receiver heights come from `window_grid`, the
// window's heights as shaded (the heights it views must outlive this object, `far` too).
class FarFieldSunShadow {
public:
    FarFieldSunShadow(const ReceiverWindow& window, const ReceiverWindow& core, const FarField& far,
                      const terrain::HeightGrid& window_grid,
                      double sun_radius_rad = SunSweepOptions{}.sun_radius_rad);

    // Sun azimuth (degrees clockwise from north) and elevation (degrees).
    void operator()(double azimuth_deg, double elevation_deg, std::vector<float>& vis) const;
    // As the renderer's hook calls it: any sun state with azimuth_deg and elevation_deg
    // (render::SunState, not named here because ts_render sits above this library).
    template <class Sun>
    void operator()(const Sun& sun, std::vector<float>& vis) const {
        (*this)(sun.azimuth_deg, sun.elevation_deg, vis);
    }

private:
    ReceiverWindow window_, core_;
    const FarField* far_;
    terrain::HeightGrid window_grid_;
    double sun_radius_rad_;
};

// The hook for render::RendererOptions::outer_sun_shadow of a scene on the window (assignable
// to it as it is).
inline FarFieldSunShadow far_field_sun_shadow(const ReceiverWindow& window, const ReceiverWindow& core,
                                              const FarField& far, const terrain::HeightGrid& window_grid) {
    return FarFieldSunShadow(window, core, far, window_grid);
}

}  // namespace ts::visibility
