#pragma once
// The transfer stage on the GPU (core/render/transfer.hpp's two steps, same layouts):
//   transfer vectors T = exp_SH(V_log + rotate(F_log, axis))   shader render_transfer.comp
//   relight          rgb = sum_i T_i L_i                          shader render_shade.comp
// The exponentiation is core/sh/sh_exp_shared.h (hybrid) or core/sh/sh_exp_squaring_shared.h
// (scaling_squaring), the same text the CPU path compiles.
//
//   gpu::Context context;
//   gpu::render::TransferField field(context, inputs);   // T computed, kept on the device
//   field.shade(light_sh, rgb);                            // per frame: one submit, rgb back
//   field.download(transfer);                              // T as [16][texels] if wanted
//
// Texels are processed in bands small enough for the device's storage-buffer range
// (maxStorageBufferRange: 128 MiB = 2.09 M texels of T on lavapipe) and its dispatch size.
#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/render/transfer.hpp"
#include "gpu/buffer.hpp"
#include "gpu/context.hpp"
#include "gpu/kernel.hpp"

namespace ts::gpu::render {

class ShadeRecording;

struct StageTime {
    std::string label;
    double ms;  // device time, summed over bands (NaN without GPU timestamps)
};

// The stage's two pipelines, each built on first use and then shared by every TransferField
// given this object (building one is slow on llvmpipe, and a renderer makes three fields).
class TransferKernels {
public:
    explicit TransferKernels(const Context& context) : context_(context) {}
    const Kernel& transfer() const;  // render_transfer.comp
    const Kernel& shade() const;     // render_shade.comp

private:
    const Context& context_;
    mutable std::optional<Kernel> transfer_, shade_;
};

class TransferField {
public:
    // Computes every texel's transfer vector on the device. The hybrid and scaling_squaring
    // exponentiations run on the GPU (runs_on_gpu; ts::InputError otherwise) with sh::ExpOptions'
    // defaults, as the CPU path; inputs.threads is ignored. Stages: upload, transfer.
    // band_texels > 0 caps the texels per band below the device's limit (tests check that bands
    // join seamlessly).
    // kernels: shared pipelines (nullptr: the field builds its own).
    TransferField(const Context& context, const ts::render::TransferInputs& inputs, std::size_t band_texels = 0,
                  std::shared_ptr<const TransferKernels> kernels = nullptr);
    // Keeps transfer vectors computed elsewhere ([16][texels], as transfer_vectors writes them)
    // on the device for shade(). Stage: upload.
    TransferField(const Context& context, const float* transfer, std::size_t texels, std::size_t band_texels = 0,
                  std::shared_ptr<const TransferKernels> kernels = nullptr);
    ~TransferField();
    TransferField(TransferField&&) noexcept;
    TransferField& operator=(TransferField&&) = delete;

    std::size_t texels() const { return texels_; }

    // T as [16][texels] (transfer.hpp's layout). Stage: download.
    void download(float* transfer_out);
    // rgb_out[t] = sum_i T[i][t] * light[i]. The first call records the commands of every band
    // (gpu/render/shade_recording.hpp); each call then re-submits them with the new light.
    // Stages: shade, and download where the radiance goes through a staging copy (a discrete
    // GPU; lavapipe's kernels write host memory directly).
    void shade(const std::array<glm::vec3, 16>& light_sh, glm::vec3* rgb_out);
    // Rewrites T of a rectangle's texels (ts::render::ShadeField::update_rect). A host copy of
    // T is made on the first call (one download); each call then uploads the rectangle's rows,
    // whole, per coefficient and band. Stage: upload.
    void update_rect(int grid_width, int col0, int row0, int w, int h, const float* transfer);

    // Per-stage device times and the wall-clock time of the last operation (the constructor,
    // download or shade).
    const std::vector<StageTime>& stages() const { return stages_; }
    double wall_ms() const { return wall_ms_; }
    int bands() const { return int(bands_.size()); }

private:
    struct Band {
        std::size_t first = 0, texels = 0;
        Buffer transfer;  // [16][padded band texels]
    };

    const Context& context_;
    std::shared_ptr<const TransferKernels> kernels_;
    std::size_t texels_ = 0;
    std::vector<Band> bands_;
    std::vector<StageTime> stages_;
    double wall_ms_ = 0;
    // The recorded per-frame relight, made by the first shade(); it refers to bands_' buffers
    // and kernels_' pipeline, so it is declared after them (and destroyed before them).
    std::unique_ptr<ShadeRecording> recording_;
    std::vector<float> host_copy_;  // [16][texels], made by the first update_rect
};

// One-shot mirrors of ts::render::transfer_vectors and shade_transfer (the second uploads T);
// both return the per-stage device times.
std::vector<StageTime> transfer_vectors(const Context& context, const ts::render::TransferInputs& inputs,
                                        float* transfer_out);
std::vector<StageTime> shade_transfer(const Context& context, const float* transfer, std::size_t texels,
                                      const std::array<glm::vec3, 16>& light_sh, glm::vec3* rgb_out);

// The exponentiation methods TransferField runs on the device: hybrid and scaling_squaring.
bool runs_on_gpu(sh::ExpMethod method);

// Texels per band on this device: the storage-buffer range over the 64 bytes of T per texel,
// and the largest one-dimensional dispatch.
std::size_t max_band_texels(const Context& context);

}  // namespace ts::gpu::render
