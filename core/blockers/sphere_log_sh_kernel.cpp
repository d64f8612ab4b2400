#include "core/blockers/sphere_log_sh_kernel.hpp"

#include <cmath>

#include "core/sh/sh_shared_float.hpp"

namespace ts::blockers {
namespace {

constexpr std::size_t kLanes = SphereLanes::kLanes;
constexpr float kTwoPi = 6.283185307179586;

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__)
#define TS_KERNEL_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"), flatten))
#else
#define TS_KERNEL_CLONES __attribute__((flatten))
#endif

struct LaneSums {
    float f[16][kLanes];
    float solid_angle[kLanes];
};

// One group of kLanes spheres at a time; each lane keeps its own sums so that the loop over the
// lanes has no dependence between iterations (the compiler vectorises it), and the lanes are
// added up once at the end.
TS_KERNEL_CLONES
void accumulate_groups(const float* __restrict px, const float* __restrict py, const float* __restrict pz,
                       const float* __restrict pr, std::size_t count, std::size_t padded, glm::vec3 q, glm::vec3 n,
                       float log_eps, bool cull, LaneSums& s) {
    for (std::size_t i = 0; i < 16; ++i)
        for (std::size_t j = 0; j < kLanes; ++j) s.f[i][j] = 0.0f;
    for (std::size_t j = 0; j < kLanes; ++j) s.solid_angle[j] = 0.0f;
    for (std::size_t g = 0; g < padded; g += kLanes) {
        for (std::size_t j = 0; j < kLanes; ++j) {
            const float vx = px[g + j] - q.x, vy = py[g + j] - q.y, vz = pz[g + j] - q.z;
            const float r = pr[g + j];
            const float d = std::sqrt(vx * vx + vy * vy + vz * vz);
            const bool inside = d <= r;
            // Inside, the cap is the whole sphere of directions and its axis does not matter.
            const float inv = inside ? 0.0f : 1.0f / d;
            const glm::vec3 dir = inside ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(vx * inv, vy * inv, vz * inv);
            float zh[4];
            sh::shared_float::ts_sphere_log_zh_rd(r, d, log_eps, zh);
            // The cap's sine and cosine as ts_sphere_log_zh_rd takes them.
            const float sb = inside ? 0.0f : r * inv;
            const float cb = inside ? -1.0f : std::sqrt((d - r) * (d + r)) * inv;
            // Culled when the whole cap lies below the tangent plane: the angle between the
            // normal and the axis exceeds 90 deg + theta_b, cos(angle) < -sin(theta_b). The
            // padding lanes past `count` are dropped the same way. A dropped sphere's ZH is
            // selected to 0 before the rotation, so every lane adds unconditionally (a masked
            // add of the 16 sums compiles to slow masked stores).
            const bool keep = g + j < count && (!cull || inside || (vx * n.x + vy * n.y + vz * n.z) * inv >= -sb);
            for (float& c : zh) c = keep ? c : 0.0f;
            float f[16];
            sh::shared_float::ts_zh_rotate(zh, dir, f);
            s.solid_angle[j] += keep ? kTwoPi * sh::shared_float::ts_one_minus_cos(cb, sb) : 0.0f;
#pragma GCC unroll 16
            for (std::size_t i = 0; i < 16; ++i) s.f[i][j] += f[i];
        }
    }
}

}  // namespace

void SphereLanes::clear() {
    x_.clear(), y_.clear(), z_.clear(), r_.clear();
    count_ = 0;
}

void SphereLanes::grow() {
    // Padding until filled (the kernel skips lanes past count_).
    x_.resize(count_ + kLanes, 0.0f), y_.resize(count_ + kLanes, 0.0f);
    z_.resize(count_ + kLanes, 0.0f), r_.resize(count_ + kLanes, 0.0f);
}

void SphereLanes::assign(std::span<const Sphere> spheres) {
    clear();
    for (const Sphere& s : spheres) push_back(s);
}

void accumulate_sphere_lanes(const SphereLanes& spheres, const glm::vec3& receiver, const glm::vec3& normal,
                             float log_eps, const RatioAttenuation& options, float out[16]) {
    if (spheres.empty()) return;
    LaneSums s;
    accumulate_groups(spheres.x(), spheres.y(), spheres.z(), spheres.radius(), spheres.size(), spheres.padded(),
                      receiver, normal, log_eps, options.cull_lower_hemisphere, s);
    float total = 0.0f;
    for (std::size_t j = 0; j < kLanes; ++j) total += s.solid_angle[j];
    const float scale = options.solid_angle_ratio && total > kTwoPi ? kTwoPi / total : 1.0f;
    for (std::size_t i = 0; i < 16; ++i) {
        float sum = 0.0f;
        for (std::size_t j = 0; j < kLanes; ++j) sum += s.f[i][j];
        out[i] += scale * sum;
    }
}

}  // namespace ts::blockers
