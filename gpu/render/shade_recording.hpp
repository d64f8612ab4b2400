#pragma once
// The per-frame relight of a TransferField (render_shade.comp over every band), recorded once
// and re-submitted each frame. A frame then costs: 256 bytes of light written into a mapped
// buffer, one vkQueueSubmit, one fence wait, and a memcpy of the radiance into the caller's
// array. No command pool, command buffer, staging buffer or descriptor set is made per frame.
//
// Where the radiance lands (chosen per band by the memory type the device gives host-visible
// buffers):
//   host-visible memory that is also device-local and host-cached (lavapipe, integrated GPUs):
//     the kernel writes it there and the host reads it directly, no copy on the device;
//   otherwise (a discrete GPU): the kernel writes device-local memory and a recorded copy
//     brings it to a host-visible buffer, as a staging download would.
// The kernel, its inputs and its push constants are those of a one-shot dispatch, so the
// radiance is bit for bit what gpu::Batch-recorded shading gives.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "gpu/buffer.hpp"
#include "gpu/command.hpp"
#include "gpu/context.hpp"
#include "gpu/descriptors.hpp"
#include "gpu/handle.hpp"
#include "gpu/kernel.hpp"
#include "gpu/render/gpu_transfer.hpp"

namespace ts::gpu::render {

// render_shade.comp's push-constant block. The kernel shades four texels per invocation, so
// T's planes and the radiance are padded to whole quads of texels.
struct ShadePush {
    std::uint32_t quads;
    std::uint32_t plane_quads;
};
// render_shade.comp's local_size_x.
inline constexpr std::uint32_t kShadeGroup = 64;
inline std::size_t padded_to_quads(std::size_t texels) { return (texels + 3) / 4 * 4; }

class ShadeRecording {
public:
    // One band of T on the device: texels [first, first + texels) of the field, planes padded
    // to whole quads (TransferField's layout). The buffers must outlive the recording.
    struct BandInput {
        std::size_t first = 0, texels = 0;
        const Buffer* transfer = nullptr;
    };

    // How the radiance reaches the host: by the memory type as above (automatic), or always
    // through the device-local buffer and a copy (staging: the discrete-GPU path, which tests
    // run on lavapipe too).
    enum class Readback { automatic, staging };

    // shade: render_shade.comp with three storage buffers and its two-word push constants.
    ShadeRecording(const Context& context, const Kernel& shade, std::span<const BandInput> bands,
                   Readback readback = Readback::automatic);
    ~ShadeRecording();
    ShadeRecording(const ShadeRecording&) = delete;
    ShadeRecording& operator=(const ShadeRecording&) = delete;

    // light: the 16 coefficients as (r, g, b, 0). Runs the recorded commands and writes every
    // band's radiance into rgb_out (the field's texels, in order). Fills stages() with the
    // device times: "shade" (the kernels) and, on the staging path, "download".
    void run(std::span<const float, 64> light, glm::vec3* rgb_out);
    const std::vector<StageTime>& stages() const { return stages_; }

    // True when every band's radiance is read straight from the memory the kernel wrote.
    bool reads_directly() const;

private:
    struct Band {
        std::size_t first = 0, texels = 0;
        Buffer device_rgb;  // the kernel's output on the staging path; empty when direct
        Buffer host_rgb;    // mapped: the kernel's output (direct) or the copy's destination
    };

    void record(const Kernel& shade, std::span<const BandInput> bands);

    const Context& context_;
    Buffer light_;  // mapped, 16 x vec4
    std::vector<Band> bands_;
    DescriptorPool descriptors_;
    DeviceHandle<VkQueryPool> timestamps_;  // null without GPU timestamps
    std::vector<const char*> mark_labels_;  // one per timestamp after the first
    CommandPool pool_;
    CommandBuffer commands_;
    Fence fence_;
    std::vector<StageTime> stages_;
};

}  // namespace ts::gpu::render
