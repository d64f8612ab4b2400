#include "gpu/render/gpu_render_backend.hpp"

#include <utility>

#include "core/util/error.hpp"
#include "gpu/render/gpu_transfer.hpp"

namespace ts::gpu::render {
namespace {

// T on the device, shaded per frame (TransferField::shade: one dispatch per band).
class GpuShadeField final : public ts::render::ShadeField {
public:
    GpuShadeField(const Context& context, const float* transfer, std::size_t texels, std::size_t band_texels,
                  std::shared_ptr<const TransferKernels> kernels)
        : field_(context, transfer, texels, band_texels, std::move(kernels)) {}
    std::size_t texels() const override { return field_.texels(); }
    void shade(const std::array<glm::vec3, 16>& light_sh, glm::vec3* rgb_out) override {
        field_.shade(light_sh, rgb_out);
    }
    void update_rect(int grid_width, int col0, int row0, int w, int h, const float* transfer) override {
        field_.update_rect(grid_width, col0, row0, w, h, transfer);
    }

private:
    TransferField field_;
};

class GpuRenderBackend final : public ts::render::RenderBackend {
public:
    GpuRenderBackend(const Context& context, const GpuBackendOptions& options)
        : context_(context), options_(options), kernels_(std::make_shared<const TransferKernels>(context)) {}

    std::string name() const override { return context_.device_info().name; }

    void transfer_vectors(const ts::render::TransferInputs& in, float* transfer_out) override {
        TransferField field(context_, in, options_.max_band_texels, kernels_);
        field.download(transfer_out);
    }

    std::unique_ptr<ts::render::ShadeField> keep_transfer(const float* transfer, std::size_t texels) override {
        return std::make_unique<GpuShadeField>(context_, transfer, texels, options_.max_band_texels, kernels_);
    }

private:
    const Context& context_;
    GpuBackendOptions options_;
    // The transfer and shade pipelines, built once for all of a renderer's fields.
    std::shared_ptr<const TransferKernels> kernels_;
};

}  // namespace

std::unique_ptr<ts::render::RenderBackend> make_gpu_backend(const Context& context, const GpuBackendOptions& options) {
    return std::make_unique<GpuRenderBackend>(context, options);
}

}  // namespace ts::gpu::render
