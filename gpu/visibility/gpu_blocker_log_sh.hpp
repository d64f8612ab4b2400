#pragma once
// The sphere blockers' log-SH accumulation on the Vulkan device (blocker_log_sh.comp): every
// sphere at every receiver, the formulas and ratio attenuation of the CPU kernel
// (core/blockers/sphere_log_sh_kernel.hpp), added to the receivers' log-SH.
#include <span>

#include <glm/vec3.hpp>

#include "core/blockers/sphere_blocker.hpp"
#include "gpu/context.hpp"
#include "gpu/kernel.hpp"

namespace ts::gpu::visibility {

class GpuBlockerLogSh {
public:
    explicit GpuBlockerLogSh(const Context& context);

    // Adds to log_sh ([coefficient][receiver], 16 x receivers.size() floats) the log-SH of the
    // spheres seen from each receiver (positions, unit normals and sphere centres in one
    // frame). Returns the wall-clock milliseconds of the device work (upload to download).
    double add(std::span<const glm::vec3> receivers, std::span<const glm::vec3> normals,
               std::span<const blockers::Sphere> spheres, float log_eps, const blockers::RatioAttenuation& options,
               std::span<float> log_sh) const;

private:
    const Context& context_;
    Kernel kernel_;
};

}  // namespace ts::gpu::visibility
