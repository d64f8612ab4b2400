#include "gpu/visibility/horizon_products.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>

#include "core/sh/sh_shared.hpp"
#include "core/sh/slice_projector.hpp"
#include "core/util/angles.hpp"
#include "core/util/progress_bar.hpp"

namespace ts::gpu::visibility {
namespace {

// Mirrors of the shaders' push-constant blocks.
struct LogShPush {  // vis_log_sh.comp
    std::uint32_t texels;
    std::int32_t directions;
    float log_eps;
};
struct SkyPush {  // vis_sky.comp
    std::uint32_t texels;
    std::int32_t directions;
};
constexpr std::uint32_t kTexelGroup = 64;  // local_size_x of vis_log_sh and vis_sky

// ts_slice_azimuth_weight of every slice and coefficient (the shared formula, in double).
std::vector<float> slice_weights(int directions) {
    std::vector<float> w(std::size_t(directions) * 16);
    for (int d = 0; d < directions; ++d)
        for (int i = 0; i < 16; ++i) {
            const int l = int(std::sqrt(double(i)));
            w[std::size_t(d) * 16 + std::size_t(i)] = float(sh::shared::ts_slice_azimuth_weight(
                i - l * l - l, sh::SliceProjector::azimuth(d, directions), 2.0 * kPi / directions));
        }
    return w;
}

}  // namespace

void add_stage_times(std::vector<StageTime>& total, const Batch& batch) {
    for (const auto& [label, ms] : batch.stage_times()) {
        auto it = std::find_if(total.begin(), total.end(), [&](const StageTime& s) { return s.label == label; });
        if (it == total.end()) total.push_back({label, ms});
        else it->ms += ms;
    }
}

HorizonProducts::HorizonProducts(const Context& context, Batch& batch, const Options& options, int width, int height,
                                 Result& result)
    : context_(context),
      options_(options),
      directions_(options.horizon.directions),
      texels_(std::size_t(width) * std::size_t(height)),
      log_sh_(context, "vis_log_sh", {.storage_buffers = 3, .push_constant_bytes = sizeof(LogShPush)}),
      sky_(context, "vis_sky", {.storage_buffers = 3, .push_constant_bytes = sizeof(SkyPush)}),
      slice_weights_(batch.upload_new(std::span<const float>(slice_weights(directions_)))) {
    result.horizons.width = width;
    result.horizons.height = height;
    result.horizons.directions = directions_;
    result.horizons.angle.assign(texels_ * std::size_t(directions_), 0.0f);
    if (options.log_sh) result.log_sh.assign(texels_ * 16, 0.0f);
    if (options.sky) {
        result.svf.assign(texels_, 0.0f);
        result.sky_visible.assign(texels_, 0.0f);
    }
}

void HorizonProducts::finish_band(Batch& batch, const Buffer& horizons, int band_row0, std::size_t band_texels,
                                  Result& result, std::size_t reported_rays) {
    std::vector<float> band_horizons(band_texels * std::size_t(directions_));
    std::vector<float> band_sh, band_svf, band_sky;
    std::unique_ptr<Buffer> sh_buffer, svf_buffer, sky_buffer;
    if (options_.log_sh) {
        sh_buffer = std::make_unique<Buffer>(context_.create_buffer(band_texels * 16 * sizeof(float)));
        batch.dispatch(log_sh_, {horizons, *sh_buffer, slice_weights_},
                       LogShPush{std::uint32_t(band_texels), directions_, options_.log_eps},
                       groups_for(band_texels, kTexelGroup));
        batch.mark("log_sh");
    }
    if (options_.sky) {
        svf_buffer = std::make_unique<Buffer>(context_.create_buffer(band_texels * sizeof(float)));
        sky_buffer = std::make_unique<Buffer>(context_.create_buffer(band_texels * sizeof(float)));
        batch.dispatch(sky_, {horizons, *svf_buffer, *sky_buffer}, SkyPush{std::uint32_t(band_texels), directions_},
                       groups_for(band_texels, kTexelGroup));
        batch.mark("sky");
    }
    batch.download(horizons, std::span<float>(band_horizons));
    if (sh_buffer) {
        band_sh.resize(band_texels * 16);
        batch.download(*sh_buffer, std::span<float>(band_sh));
    }
    if (svf_buffer) {
        band_svf.resize(band_texels);
        band_sky.resize(band_texels);
        batch.download(*svf_buffer, std::span<float>(band_svf));
        batch.download(*sky_buffer, std::span<float>(band_sky));
    }
    batch.mark("download");
    batch.submit_and_wait();
    add_stage_times(result.stages, batch);
    ++result.bands;

    // The band's rows into the window-wide layouts ([plane][texel]).
    const std::size_t offset = std::size_t(band_row0) * std::size_t(result.horizons.width);
    auto place = [&](const std::vector<float>& from, auto& to, int planes) {
        for (int i = 0; i < planes; ++i)
            std::memcpy(to.data() + std::size_t(i) * texels_ + offset, from.data() + std::size_t(i) * band_texels,
                        band_texels * sizeof(float));
    };
    place(band_horizons, result.horizons.angle, directions_);
    if (options_.log_sh) place(band_sh, result.log_sh, 16);
    if (options_.sky) {
        place(band_svf, result.svf, 1);
        place(band_sky, result.sky_visible, 1);
    }
    const std::size_t rays = band_texels * std::size_t(directions_);
    if (options_.horizon.progress && rays > reported_rays) options_.horizon.progress->advance(rays - reported_rays);
}

}  // namespace ts::gpu::visibility
