#pragma once
// The sphere blockers' log-SH accumulation on the Vulkan device (blocker_log_sh.comp): every
// sphere of a mesh at every receiver it counts for, the formulas and ratio attenuation of the
// CPU kernel (core/blockers/sphere_log_sh_kernel.hpp), added to the receivers' log-SH.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/blockers/sphere_blocker.hpp"
#include "gpu/context.hpp"
#include "gpu/kernel.hpp"

namespace ts::gpu::visibility {

// What one receiver sees of one mesh: its position in that mesh's frame and the mesh's spheres
// as a range of the sphere list.
struct GpuBlockerEntry {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    std::uint32_t first_sphere = 0, sphere_count = 0;
};

class GpuBlockerLogSh {
public:
    explicit GpuBlockerLogSh(const Context& context);

    // Adds to log_sh ([coefficient][receiver], 16 x receivers.size() floats) the log-SH of the
    // spheres seen from each receiver (positions, unit normals and sphere centres in one
    // frame). Returns the wall-clock milliseconds of the device work (upload to download).
    double add(std::span<const glm::vec3> receivers, std::span<const glm::vec3> normals,
               std::span<const blockers::Sphere> spheres, float log_eps, const blockers::RatioAttenuation& options,
               std::span<float> log_sh) const;

    // The receivers of several meshes: `entries` grouped by receiver (the entries of one receiver
    // consecutive, `receiver_of[e]` its index into log_sh's [coefficient][receiver] columns,
    // `receivers` of them). Each receiver adds the sum of its entries, scaled once by the ratio
    // attenuation over all their kept caps. Returns the device milliseconds.
    double add(std::span<const GpuBlockerEntry> entries, std::span<const std::uint32_t> receiver_of,
               std::size_t receivers, std::span<const blockers::Sphere> spheres, float log_eps,
               const blockers::RatioAttenuation& options, std::span<float> log_sh) const;

private:
    const Context& context_;
    Kernel kernel_;
};

}  // namespace ts::gpu::visibility
