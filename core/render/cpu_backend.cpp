// The CPU RenderBackend: each stage is the core/ function it names, unchanged, so it is the
// reference the Vulkan backend is tested against and a way to run FrameRenderer's backend path
// (unfused per-frame shading over the full [16][texels] T) on the CPU.
#include <algorithm>
#include <stdexcept>
#include <vector>

#include "core/render/render_backend.hpp"

namespace ts::render {
namespace {

class CpuShadeField final : public ShadeField {
public:
    CpuShadeField(const float* transfer, std::size_t texels, int threads)
        : transfer_(transfer, transfer + 16 * texels), texels_(texels), threads_(threads) {}
    std::size_t texels() const override { return texels_; }
    void shade(const std::array<glm::vec3, 16>& light_sh, glm::vec3* rgb_out) override {
        shade_transfer(transfer_.data(), texels_, light_sh, rgb_out, threads_);
    }
    void update_rect(int grid_width, int col0, int row0, int w, int h, const float* transfer) override {
        if (w <= 0 || h <= 0) return;
        if (col0 < 0 || row0 < 0 || col0 + w > grid_width || std::size_t(row0 + h) * std::size_t(grid_width) > texels_)
            throw std::invalid_argument("ShadeField::update_rect: rectangle outside the texels");
        const std::size_t n = std::size_t(w) * std::size_t(h);
        for (int i = 0; i < 16; ++i)
            for (int r = 0; r < h; ++r)
                std::copy_n(transfer + std::size_t(i) * n + std::size_t(r) * std::size_t(w), std::size_t(w),
                            transfer_.begin() + std::ptrdiff_t(std::size_t(i) * texels_ +
                                                               std::size_t(row0 + r) * std::size_t(grid_width) +
                                                               std::size_t(col0)));
    }

private:
    std::vector<float> transfer_;
    std::size_t texels_;
    int threads_;
};

class CpuBackend final : public RenderBackend {
public:
    explicit CpuBackend(int threads) : threads_(threads) {}
    std::string name() const override { return "cpu"; }

    void transfer_vectors(const TransferInputs& in, float* transfer_out) override {
        TransferInputs with_threads = in;
        with_threads.threads = threads_;
        render::transfer_vectors(with_threads, transfer_out);
    }

    std::unique_ptr<ShadeField> keep_transfer(const float* transfer, std::size_t texels) override {
        if (texels > 0 && !transfer) throw std::invalid_argument("RenderBackend::keep_transfer: null transfer");
        return std::make_unique<CpuShadeField>(transfer, texels, threads_);
    }

private:
    int threads_;
};

}  // namespace

std::unique_ptr<RenderBackend> make_cpu_backend(int threads) { return std::make_unique<CpuBackend>(threads); }

}  // namespace ts::render
