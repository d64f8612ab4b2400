#include "gpu/visibility/gpu_blocker_log_sh.hpp"

#include <cstdint>
#include <stdexcept>
#include <vector>

#include <glm/vec4.hpp>

#include "gpu/batch.hpp"

namespace ts::gpu::visibility {
namespace {

// Mirrors the push constants of blocker_log_sh.comp.
struct Push {
    std::uint32_t receivers;
    std::uint32_t spheres;
    float log_eps;
    std::uint32_t cull_lower_hemisphere;
    std::uint32_t solid_angle_ratio;
};

std::vector<glm::vec4> as_vec4(std::span<const glm::vec3> v) {
    std::vector<glm::vec4> out;
    out.reserve(v.size());
    for (const glm::vec3& x : v) out.emplace_back(x, 0.0f);
    return out;
}

}  // namespace

GpuBlockerLogSh::GpuBlockerLogSh(const Context& context)
    : context_(context),
      kernel_(context, "blocker_log_sh", {.storage_buffers = 4, .push_constant_bytes = sizeof(Push)}) {}

double GpuBlockerLogSh::add(std::span<const glm::vec3> receivers, std::span<const glm::vec3> normals,
                            std::span<const blockers::Sphere> spheres, float log_eps,
                            const blockers::RatioAttenuation& options, std::span<float> log_sh) const {
    if (normals.size() != receivers.size() || log_sh.size() != 16 * receivers.size())
        throw std::invalid_argument("GpuBlockerLogSh::add: receivers, normals and log_sh sizes disagree");
    if (receivers.empty() || spheres.empty()) return 0.0;
    std::vector<glm::vec4> s;
    s.reserve(spheres.size());
    for (const blockers::Sphere& b : spheres) s.emplace_back(glm::vec3(b.center), float(b.radius));
    const std::vector<glm::vec4> q = as_vec4(receivers), n = as_vec4(normals);
    Batch batch(context_);
    const Buffer qb = batch.upload_new(std::span<const glm::vec4>(q));
    const Buffer nb = batch.upload_new(std::span<const glm::vec4>(n));
    const Buffer sb = batch.upload_new(std::span<const glm::vec4>(s));
    const Buffer out = batch.upload_new(std::span<const float>(log_sh.data(), log_sh.size()));
    const Push push{std::uint32_t(receivers.size()), std::uint32_t(spheres.size()), log_eps,
                    options.cull_lower_hemisphere ? 1u : 0u, options.solid_angle_ratio ? 1u : 0u};
    batch.dispatch(kernel_, {qb, nb, sb, out}, push, groups_for(receivers.size(), 64));
    batch.download(out, log_sh);
    batch.submit_and_wait();
    return batch.last_run_ms();
}

}  // namespace ts::gpu::visibility
