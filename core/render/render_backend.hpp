#pragma once
// Where the renderer's transfer stages run. core/ knows only this interface: the CPU
// implementation (make_cpu_backend()) is the reference; gpu/render provides a Vulkan one
// (gpu/render/gpu_render_backend.hpp). Horizons and log-SH have their own seam
// (core/visibility/visibility_backend.hpp).
//
//   one-time:  transfer vectors T            -> transfer_vectors
//              T kept for per-frame shading  -> keep_transfer
//   per frame: rgb_t = sum_i T_i,t L_i        -> ShadeField::shade
//
// Every stage returns what the CPU function it names returns, within tolerances the tests state.
#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/render/transfer.hpp"

namespace ts::render {

// Transfer vectors held where the shading runs (host memory or device memory).
class ShadeField {
public:
    virtual ~ShadeField() = default;
    virtual std::size_t texels() const = 0;
    // rgb_out[t] = sum_i T[i][t] * light_sh[i] (as shade_transfer); NaN texels give NaN.
    virtual void shade(const std::array<glm::vec3, 16>& light_sh, glm::vec3* rgb_out) = 0;
    // Rewrites T of the texels of a rectangle: columns [col0, col0 + w), rows [row0, row0 + h)
    // of a grid `grid_width` texels wide (texel t = row * grid_width + col); `transfer` is
    // [16][w * h], the rectangle's texels row-major (a moving mesh's footprint).
    virtual void update_rect(int grid_width, int col0, int row0, int w, int h, const float* transfer) = 0;
};

class RenderBackend {
public:
    virtual ~RenderBackend() = default;
    // "cpu" or the Vulkan device's name, for logs and bench output.
    virtual std::string name() const = 0;
    // As render::transfer_vectors (in.method: at least hybrid and scaling_squaring).
    virtual void transfer_vectors(const TransferInputs& in, float* transfer_out) = 0;
    // Keeps a copy of T ([16][texels], as transfer_vectors writes it) for per-frame shading.
    virtual std::unique_ptr<ShadeField> keep_transfer(const float* transfer, std::size_t texels) = 0;
};

// The CPU reference backend (transfer_vectors, shade_transfer)
// with `threads` workers (0 = one per core).
std::unique_ptr<RenderBackend> make_cpu_backend(int threads = 0);

}  // namespace ts::render
