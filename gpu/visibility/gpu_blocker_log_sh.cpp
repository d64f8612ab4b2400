#include "gpu/visibility/gpu_blocker_log_sh.hpp"

#include <cstdint>
#include <stdexcept>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "gpu/batch.hpp"

namespace ts::gpu::visibility {
namespace {

// Mirrors the push constants of blocker_log_sh.comp.
struct Push {
    std::uint32_t entries;
    float log_eps;
    std::uint32_t cull_lower_hemisphere;
};

constexpr float kTwoPi = 6.283185307179586f;

}  // namespace

GpuBlockerLogSh::GpuBlockerLogSh(const Context& context)
    : context_(context),
      kernel_(context, "blocker_log_sh", {.storage_buffers = 5, .push_constant_bytes = sizeof(Push)}) {}

double GpuBlockerLogSh::add(std::span<const glm::vec3> receivers, std::span<const glm::vec3> normals,
                            std::span<const blockers::Sphere> spheres, float log_eps,
                            const blockers::RatioAttenuation& options, std::span<float> log_sh) const {
    if (normals.size() != receivers.size() || log_sh.size() != 16 * receivers.size())
        throw std::invalid_argument("GpuBlockerLogSh::add: receivers, normals and log_sh sizes disagree");
    std::vector<GpuBlockerEntry> entries(receivers.size());
    std::vector<std::uint32_t> receiver_of(receivers.size());
    for (std::size_t k = 0; k < receivers.size(); ++k) {
        entries[k] = {receivers[k], normals[k], 0u, std::uint32_t(spheres.size())};
        receiver_of[k] = std::uint32_t(k);
    }
    return add(entries, receiver_of, receivers.size(), spheres, log_eps, options, log_sh);
}

double GpuBlockerLogSh::add(std::span<const GpuBlockerEntry> entries, std::span<const std::uint32_t> receiver_of,
                            std::size_t receivers, std::span<const blockers::Sphere> spheres, float log_eps,
                            const blockers::RatioAttenuation& options, std::span<float> log_sh) const {
    if (receiver_of.size() != entries.size() || log_sh.size() != 16 * receivers)
        throw std::invalid_argument("GpuBlockerLogSh::add: entries, receivers and log_sh sizes disagree");
    for (std::size_t e = 0; e < entries.size(); ++e)
        if (receiver_of[e] >= receivers || (e > 0 && receiver_of[e] < receiver_of[e - 1]) ||
            std::uint64_t(entries[e].first_sphere) + entries[e].sphere_count > spheres.size())
            throw std::invalid_argument("GpuBlockerLogSh::add: entries out of order or past the spheres");
    if (entries.empty() || spheres.empty()) return 0.0;
    const std::size_t n = entries.size();
    std::vector<glm::vec4> q(n), nn(n), s;
    std::vector<glm::uvec2> ranges(n);
    for (std::size_t e = 0; e < n; ++e) {
        q[e] = glm::vec4(entries[e].position, 0.0f), nn[e] = glm::vec4(entries[e].normal, 0.0f);
        ranges[e] = {entries[e].first_sphere, entries[e].sphere_count};
    }
    s.reserve(spheres.size());
    for (const blockers::Sphere& b : spheres) s.emplace_back(glm::vec3(b.center), float(b.radius));
    std::vector<float> sums(17 * n);
    Batch batch(context_);
    const Buffer qb = batch.upload_new(std::span<const glm::vec4>(q));
    const Buffer nb = batch.upload_new(std::span<const glm::vec4>(nn));
    const Buffer rb = batch.upload_new(std::span<const glm::uvec2>(ranges));
    const Buffer sb = batch.upload_new(std::span<const glm::vec4>(s));
    const Buffer out = batch.upload_new(std::span<const float>(sums));
    const Push push{std::uint32_t(n), log_eps, options.cull_lower_hemisphere ? 1u : 0u};
    batch.dispatch(kernel_, {qb, nb, rb, sb, out}, push, groups_for(n, 64));
    batch.download(out, std::span<float>(sums));
    batch.submit_and_wait();
    // Each receiver: its entries' sums together, scaled so the kept caps claim at most 2 pi.
    for (std::size_t e0 = 0; e0 < n;) {
        std::size_t e1 = e0;
        float solid = 0.0f;
        while (e1 < n && receiver_of[e1] == receiver_of[e0]) solid += sums[16 * n + e1++];
        const float scale = options.solid_angle_ratio && solid > kTwoPi ? kTwoPi / solid : 1.0f;
        const std::size_t t = receiver_of[e0];
        for (std::size_t i = 0; i < 16; ++i) {
            float sum = 0.0f;
            for (std::size_t e = e0; e < e1; ++e) sum += sums[i * n + e];
            log_sh[i * receivers + t] += scale * sum;
        }
        e0 = e1;
    }
    return batch.last_run_ms();
}

}  // namespace ts::gpu::visibility
