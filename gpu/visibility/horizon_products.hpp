#pragma once
// What every GPU horizon method (the exact sweep, gpu_visibility.cpp; the pyramid march,
// gpu_pyramid.cpp) does once a band of receivers has its horizons on the device: log-SH
// (vis_log_sh.comp), svf and sky_visible (vis_sky.comp), the download, and the band's rows
// placed into the window-wide Result layouts ([plane][texel]).
//
//   Batch batch(context);
//   HorizonProducts products(context, batch, options, win.width, win.height, result);  // sizes result
//   ... per band: record the horizons into `horizons` ([direction][band texel]), then
//   products.finish_band(batch, horizons, band_row0, band_texels, result);
#include <cstddef>
#include <vector>

#include "gpu/batch.hpp"
#include "gpu/buffer.hpp"
#include "gpu/context.hpp"
#include "gpu/kernel.hpp"
#include "gpu/visibility/gpu_visibility.hpp"

namespace ts::gpu::visibility {

// Adds a submitted batch's per-label device times into `total` (labels summed over batches).
void add_stage_times(std::vector<StageTime>& total, const Batch& batch);

class HorizonProducts {
public:
    // Sizes `result` for a width x height window with options.horizon.directions azimuths
    // (horizons always; log_sh, svf and sky_visible as `options` asks) and records the upload of
    // the log-SH slice weights into `batch` (submitted by the caller with its own uploads).
    HorizonProducts(const Context& context, Batch& batch, const Options& options, int width, int height,
                    Result& result);

    // Records log-SH and sky for the band whose horizons are in `horizons`, downloads them,
    // submits and waits, adds the stage times, copies the band's rows (window rows from
    // band_row0 on) into `result` and advances the progress bar by the band's rays that the
    // caller has not reported already (`reported_rays`, e.g. azimuths swept in earlier submits).
    void finish_band(Batch& batch, const Buffer& horizons, int band_row0, std::size_t band_texels, Result& result,
                     std::size_t reported_rays = 0);

private:
    const Context& context_;
    const Options& options_;
    int directions_;
    std::size_t texels_;
    Kernel log_sh_, sky_;
    Buffer slice_weights_;
};

}  // namespace ts::gpu::visibility
