#include "gpu/render/gpu_transfer.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <stdexcept>

#include "core/sh/exp_method.hpp"
#include "core/sh/sh_exp.hpp"
#include "core/sh/sh_exp_shared.hpp"
#include "core/sh/sh_exp_squaring_shared.hpp"
#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"
#include "core/util/stopwatch.hpp"
#include "gpu/batch.hpp"
#include "gpu/render/shade_recording.hpp"

namespace ts::gpu::render {
namespace {

constexpr VkDeviceSize kCoeffs = 16;

// Mirrors of the shaders' push-constant blocks.
struct TransferPush {
    std::uint32_t texels;
    std::uint32_t stride;
    std::uint32_t uniform_lobe;
    float threshold;
    std::int32_t max_squarings;
    std::int32_t method;  // TS_TRANSFER_EXP_*
    float squaring_threshold;
    std::int32_t squaring_base_order;
};


// The lighting SH as render_shade.comp reads it: one (r, g, b, 0) per coefficient.
std::array<float, kCoeffs * 4> light_vec4(const std::array<glm::vec3, 16>& light_sh) {
    std::array<float, kCoeffs * 4> light{};
    for (std::size_t i = 0; i < kCoeffs; ++i)
        for (int c = 0; c < 3; ++c) light[4 * i + std::size_t(c)] = light_sh[i][c];
    return light;
}

ShadePush shade_push(std::size_t texels) {
    return {std::uint32_t(padded_to_quads(texels) / 4), std::uint32_t(padded_to_quads(texels) / 4)};
}

constexpr std::uint32_t kGroup = 64;  // render_transfer.comp's local_size_x
// Bands per submit: each adds two timestamp marks, at most Batch::kMaxMarks per submit.
constexpr std::size_t kBandsPerSubmit = 16;

void add_stage_times(std::vector<StageTime>& total, const Batch& batch) {
    for (const auto& [label, ms] : batch.stage_times()) {
        auto it = std::find_if(total.begin(), total.end(), [&](const StageTime& s) { return s.label == label; });
        if (it == total.end()) total.push_back({label, ms});
        else it->ms += ms;
    }
}

template <typename T>
std::span<const std::byte> bytes_of(const T* data, std::size_t count) {
    return std::as_bytes(std::span<const T>(data, count));
}

}  // namespace

bool runs_on_gpu(sh::ExpMethod method) {
    return method == sh::ExpMethod::hybrid || method == sh::ExpMethod::scaling_squaring;
}

namespace {
// A field without shared kernels builds both pipelines up front, so its first operation's
// timings (bench transfer) hold no pipeline creation.
std::shared_ptr<const TransferKernels> own_kernels(const Context& context) {
    auto kernels = std::make_shared<const TransferKernels>(context);
    kernels->transfer();
    kernels->shade();
    return kernels;
}
}  // namespace

std::size_t max_band_texels(const Context& context) {
    const VkDeviceSize by_range = context.limits().maxStorageBufferRange / (kCoeffs * sizeof(float));
    const VkDeviceSize by_groups = VkDeviceSize(context.limits().maxComputeWorkGroupCount[0]) * kGroup;
    return std::size_t(std::max<VkDeviceSize>(kGroup, std::min(by_range, by_groups) / 4 * 4));
}

const Kernel& TransferKernels::transfer() const {
    if (!transfer_)
        transfer_.emplace(context_, "render_transfer",
                          KernelLayout{.storage_buffers = 5, .push_constant_bytes = sizeof(TransferPush)});
    return *transfer_;
}

const Kernel& TransferKernels::shade() const {
    if (!shade_)
        shade_.emplace(context_, "render_shade",
                       KernelLayout{.storage_buffers = 3, .push_constant_bytes = sizeof(ShadePush)});
    return *shade_;
}

TransferField::TransferField(const Context& context, const ts::render::TransferInputs& in, std::size_t band_texels,
                             std::shared_ptr<const TransferKernels> kernels)
    : context_(context),
      kernels_(kernels ? std::move(kernels) : own_kernels(context)),
      texels_(in.texels) {
    if (!runs_on_gpu(in.method))
        throw QuantityError(Quantity::exp_method, std::string(sh::to_string(in.method)),
                            "only hybrid and scaling_squaring run on the GPU (compute on the CPU)");
    if (texels_ == 0) return;
    if (!in.log_visibility || !in.lobe_axis || !in.lobe_log_zh)
        throw std::invalid_argument("gpu::render::TransferField: null input array");
    std::size_t band = max_band_texels(context);
    if (band_texels > 0) band = std::min(band, band_texels);

    const sh::ExpOptions exp_options;  // the CPU path's hybrid threshold and squaring cap
    const Stopwatch start;
    stages_.clear();
    Batch batch(context);
    static_assert(sizeof(sh::exp_shared::TsLinearRow) == 3 * sizeof(float));
    const Buffer linear_table = batch.upload_new(std::span<const sh::exp_shared::TsLinearRow>(
        sh::exp_shared::kTsLinearTable, std::size_t(TS_LINEAR_ROWS)));
    Buffer uniform_zh;
    if (in.uniform_lobe) {
        uniform_zh = context.create_buffer(4 * sizeof(float));
        batch.upload(uniform_zh, bytes_of(in.lobe_log_zh, 4));
    }
    for (std::size_t first = 0; first < texels_; first += band) {
        const std::size_t n = std::min(band, texels_ - first);
        Band b{first, n, context.create_buffer(padded_to_quads(n) * kCoeffs * sizeof(float))};
        // The band's inputs live until this band's submit.
        const Buffer log_vis = context.create_buffer(n * kCoeffs * sizeof(float));
        const Buffer axis = context.create_buffer(n * 3 * sizeof(float));
        Buffer zh;
        for (VkDeviceSize i = 0; i < kCoeffs; ++i)
            batch.upload(log_vis, bytes_of(in.log_visibility + i * texels_ + first, n), i * n * sizeof(float));
        batch.upload(axis, bytes_of(in.lobe_axis + 3 * first, 3 * n));
        if (!in.uniform_lobe) {
            zh = context.create_buffer(n * 4 * sizeof(float));
            batch.upload(zh, bytes_of(in.lobe_log_zh + 4 * first, 4 * n));
        }
        if (padded_to_quads(n) != n) batch.fill(b.transfer);  // the last quad's spare texels: zeros
        batch.mark("upload");
        batch.dispatch(kernels_->transfer(), {log_vis, axis, in.uniform_lobe ? uniform_zh : zh, b.transfer, linear_table},
                       TransferPush{std::uint32_t(n), std::uint32_t(padded_to_quads(n)), in.uniform_lobe ? 1u : 0u,
                                    exp_options.hybrid_threshold, exp_options.max_squarings,
                                    in.method == sh::ExpMethod::hybrid ? TS_TRANSFER_EXP_HYBRID
                                                                       : TS_TRANSFER_EXP_SCALING_SQUARING,
                                    exp_options.squaring_threshold, exp_options.squaring_base_order},
                       groups_for(n, kGroup));
        batch.mark("transfer");
        batch.submit_and_wait();
        add_stage_times(stages_, batch);
        bands_.push_back(std::move(b));
    }
    wall_ms_ = start.milliseconds();
}

TransferField::TransferField(const Context& context, const float* transfer, std::size_t texels,
                             std::size_t band_texels, std::shared_ptr<const TransferKernels> kernels)
    : context_(context),
      kernels_(kernels ? std::move(kernels) : own_kernels(context)),
      texels_(texels) {
    if (texels_ == 0) return;
    if (!transfer) throw std::invalid_argument("gpu::render::TransferField: null transfer array");
    std::size_t band = max_band_texels(context);
    if (band_texels > 0) band = std::min(band, band_texels);
    const Stopwatch start;
    stages_.clear();
    Batch batch(context);
    for (std::size_t first = 0; first < texels_; first += band) {
        const std::size_t n = std::min(band, texels_ - first);
        Band b{first, n, context.create_buffer(padded_to_quads(n) * kCoeffs * sizeof(float))};
        if (padded_to_quads(n) != n) batch.fill(b.transfer);  // the last quad's spare texels: zeros
        for (VkDeviceSize i = 0; i < kCoeffs; ++i)
            batch.upload(b.transfer, bytes_of(transfer + i * texels_ + first, n), i * padded_to_quads(n) * sizeof(float));
        batch.mark("upload");
        bands_.push_back(std::move(b));
        // Staging memory is held until the submit: one band (<= 128 MiB) per submit.
        batch.submit_and_wait();
        add_stage_times(stages_, batch);
    }
    wall_ms_ = start.milliseconds();
}

void TransferField::download(float* transfer_out) {
    stages_.clear();
    if (texels_ == 0) return;
    const Stopwatch start;
    Batch batch(context_);
    for (std::size_t k = 0; k < bands_.size(); ++k) {
        const Band& b = bands_[k];
        for (VkDeviceSize i = 0; i < kCoeffs; ++i)
            batch.download(b.transfer, std::span<float>(transfer_out + i * texels_ + b.first, b.texels),
                           i * padded_to_quads(b.texels) * sizeof(float));
        batch.mark("download");
        if ((k + 1) % kBandsPerSubmit == 0) {
            batch.submit_and_wait();
            add_stage_times(stages_, batch);
        }
    }
    batch.submit_and_wait();
    add_stage_times(stages_, batch);
    wall_ms_ = start.milliseconds();
}

TransferField::~TransferField() = default;
TransferField::TransferField(TransferField&&) noexcept = default;

void TransferField::shade(const std::array<glm::vec3, 16>& light_sh, glm::vec3* rgb_out) {
    stages_.clear();
    if (texels_ == 0) return;
    const Stopwatch start;
    if (!recording_) {
        std::vector<ShadeRecording::BandInput> inputs;
        for (const Band& b : bands_) inputs.push_back({b.first, b.texels, &b.transfer});
        recording_ = std::make_unique<ShadeRecording>(context_, kernels_->shade(), inputs);
    }
    const auto light = light_vec4(light_sh);
    recording_->run(std::span<const float, kCoeffs * 4>(light), rgb_out);
    stages_ = recording_->stages();
    wall_ms_ = start.milliseconds();
}

void TransferField::update_rect(int grid_width, int col0, int row0, int w, int h, const float* transfer) {
    if (w <= 0 || h <= 0) return;
    if (col0 < 0 || row0 < 0 || col0 + w > grid_width || std::size_t(row0 + h) * std::size_t(grid_width) > texels_)
        throw std::invalid_argument("gpu::render::TransferField::update_rect: rectangle outside the texels");
    if (host_copy_.empty()) {
        host_copy_.resize(kCoeffs * texels_);
        download(host_copy_.data());
    }
    const std::size_t n = std::size_t(w) * std::size_t(h);
    for (std::size_t i = 0; i < kCoeffs; ++i)
        for (int r = 0; r < h; ++r)
            std::copy_n(transfer + i * n + std::size_t(r) * std::size_t(w), std::size_t(w),
                        host_copy_.begin() + std::ptrdiff_t(i * texels_ + std::size_t(row0 + r) * std::size_t(grid_width) +
                                                            std::size_t(col0)));
    // The rows' span, whole: one upload per coefficient and band.
    const std::size_t first = std::size_t(row0) * std::size_t(grid_width);
    const std::size_t last = std::size_t(row0 + h) * std::size_t(grid_width);
    stages_.clear();
    const Stopwatch start;
    Batch batch(context_);
    for (const Band& b : bands_) {
        const std::size_t a = std::max(first, b.first), e = std::min(last, b.first + b.texels);
        if (a >= e) continue;
        for (VkDeviceSize i = 0; i < kCoeffs; ++i)
            batch.upload(b.transfer, bytes_of(host_copy_.data() + i * texels_ + a, e - a),
                         (i * padded_to_quads(b.texels) + (a - b.first)) * sizeof(float));
        batch.mark("upload");
    }
    batch.submit_and_wait();
    add_stage_times(stages_, batch);
    wall_ms_ = start.milliseconds();
}

std::vector<StageTime> transfer_vectors(const Context& context, const ts::render::TransferInputs& inputs,
                                        float* transfer_out) {
    TransferField field(context, inputs);
    std::vector<StageTime> stages = field.stages();
    field.download(transfer_out);
    stages.insert(stages.end(), field.stages().begin(), field.stages().end());
    return stages;
}

std::vector<StageTime> shade_transfer(const Context& context, const float* transfer, std::size_t texels,
                                      const std::array<glm::vec3, 16>& light_sh, glm::vec3* rgb_out) {
    std::vector<StageTime> stages;
    if (texels == 0) return stages;
    const Kernel kernel(context, "render_shade", {.storage_buffers = 3, .push_constant_bytes = sizeof(ShadePush)});
    const std::size_t band = max_band_texels(context);
    const auto light = light_vec4(light_sh);
    Batch batch(context);
    const Buffer light_buffer = batch.upload_new(std::span<const float>(light.data(), light.size()));
    for (std::size_t first = 0; first < texels; first += band) {
        const std::size_t n = std::min(band, texels - first);
        const Buffer t = context.create_buffer(padded_to_quads(n) * kCoeffs * sizeof(float));
        const Buffer rgb = context.create_buffer(padded_to_quads(n) * 3 * sizeof(float));
        if (padded_to_quads(n) != n) batch.fill(t);  // the quad's spare texels: zeros, not stale memory
        for (VkDeviceSize i = 0; i < kCoeffs; ++i)
            batch.upload(t, bytes_of(transfer + i * texels + first, n), i * padded_to_quads(n) * sizeof(float));
        batch.mark("upload");
        batch.dispatch(kernel, {t, light_buffer, rgb}, shade_push(n), groups_for(padded_to_quads(n) / 4, kShadeGroup));
        batch.mark("shade");
        batch.download(rgb, std::span<glm::vec3>(rgb_out + first, n));
        batch.mark("download");
        batch.submit_and_wait();
        add_stage_times(stages, batch);
    }
    return stages;
}

}  // namespace ts::gpu::render
