#include "core/blockers/sphere_log_sh_kernel.hpp"

#include <cmath>
#include <limits>

#include "core/sh/sh_shared_float.hpp"

namespace ts::blockers {
namespace {

constexpr std::size_t kLanes = SphereLanes::kLanes;
constexpr float kTwoPi = 6.283185307179586;
// Receivers are metres in a local frame (|coordinate| < 1e8); the square of this stays finite.
constexpr float kPaddingDistance = 1e15f;

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__)
#define TS_KERNEL_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"), flatten))
#else
#define TS_KERNEL_CLONES __attribute__((flatten))
#endif

struct LaneSums {
    float f[16][kLanes];
    float solid_angle[kLanes];  // the kept caps' 1 - cos tb
};

// The degree l of coefficient i = l*l + l + m.
constexpr int kDegree[16] = {0, 1, 1, 1, 2, 2, 2, 2, 2, 3, 3, 3, 3, 3, 3, 3};

// One group of kLanes spheres at a time; each lane keeps its own sums so that the loop over the
// lanes has no dependence between iterations (the compiler vectorises it), and the lanes are
// added up once at the end. Per pair: two square roots and one division (ts_sphere_cap_rd), the
// cap's shape and the basis polynomials; the constant factors of each coefficient
// (coefficient_factors) are applied once per receiver, by the caller.
TS_KERNEL_CLONES
void accumulate_groups(const float* __restrict px, const float* __restrict py, const float* __restrict pz,
                       const float* __restrict pr, std::size_t padded, glm::vec3 q, glm::vec3 n, bool cull,
                       LaneSums& s) {
    // Inside a sphere inv = sb = 0, so the test reads 0 >= 0 and keeps it; without culling the
    // floor is -inf. (A scalar bool in the lanes' condition stops GCC vectorising the loop.)
    const float cull_floor = cull ? 0.0f : -std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < 16; ++i)
        for (std::size_t j = 0; j < kLanes; ++j) s.f[i][j] = 0.0f;
    for (std::size_t j = 0; j < kLanes; ++j) s.solid_angle[j] = 0.0f;
    for (std::size_t g = 0; g < padded; g += kLanes) {
        for (std::size_t j = 0; j < kLanes; ++j) {
            const float vx = px[g + j] - q.x, vy = py[g + j] - q.y, vz = pz[g + j] - q.z;
            const float r = pr[g + j];
            const float d = std::sqrt(vx * vx + vy * vy + vz * vz);
            float cap[4];  // 1/d, cos, sin and 1 - cos of the cap (0, -1, 0, 2 inside)
            sh::shared_float::ts_sphere_cap_rd(r, d, cap);
            const float inv = cap[0], cb = cap[1], sb = cap[2];
            // Inside, the cap is the whole sphere of directions and its axis does not matter.
            const glm::vec3 dir = d <= r ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(vx * inv, vy * inv, vz * inv);
            float shape[4];
            sh::shared_float::ts_cap_zh_shape(cb, sb, cap[3], shape);
            // Culled when the whole cap lies below the tangent plane: the angle between the
            // normal and the axis exceeds 90 deg + theta_b, cos(angle) < -sin(theta_b). The
            // padding lanes (radius -1, far away: SphereLanes::grow) are dropped too. A dropped
            // sphere's shape is selected to 0, so every lane adds unconditionally (a masked add
            // of the 16 sums compiles to slow masked stores).
            const bool keep = r >= 0.0f && (vx * n.x + vy * n.y + vz * n.z) * inv + sb >= cull_floor;
            for (float& c : shape) c = keep ? c : 0.0f;
            float poly[16];
            sh::shared_float::ts_sh_poly(dir, poly);
            s.solid_angle[j] += shape[0];
#pragma GCC unroll 16
            for (std::size_t i = 0; i < 16; ++i) s.f[i][j] += shape[kDegree[i]] * poly[i];
        }
    }
}

// What ts_zh_rotate(ts_cap_log_zh_omc(...)) multiplies coefficient i's shape x polynomial by:
// log_eps, the cap's and the rotation's factors of its degree, the basis function's norm.
void coefficient_factors(float log_eps, float out[16]) {
    float cap[4], rotation[4], norm[16];
    sh::shared_float::ts_cap_zh_norms(cap);
    sh::shared_float::ts_zh_rotate_norms(rotation);
    sh::shared_float::ts_sh_norms(norm);
    for (int i = 0; i < 16; ++i) out[i] = log_eps * cap[kDegree[i]] * rotation[kDegree[i]] * norm[i];
}

}  // namespace

void SphereLanes::clear() {
    x_.clear(), y_.clear(), z_.clear(), r_.clear();
    count_ = 0;
}

void SphereLanes::grow() {
    // Padding until filled: a negative radius, which the kernel drops, far from any receiver so
    // that no lane divides by a zero distance (every lane is computed, kept or not).
    x_.resize(count_ + kLanes, kPaddingDistance), y_.resize(count_ + kLanes, 0.0f);
    z_.resize(count_ + kLanes, 0.0f), r_.resize(count_ + kLanes, -1.0f);
}

void SphereLanes::assign(std::span<const Sphere> spheres) {
    clear();
    for (const Sphere& s : spheres) push_back(s);
}

void accumulate_sphere_lanes(const SphereLanes& spheres, const glm::vec3& receiver, const glm::vec3& normal,
                             float log_eps, const RatioAttenuation& options, float out[16]) {
    if (spheres.empty()) return;
    LaneSums s;
    accumulate_groups(spheres.x(), spheres.y(), spheres.z(), spheres.radius(), spheres.padded(), receiver, normal,
                      options.cull_lower_hemisphere, s);
    float total = 0.0f;  // sum of the kept caps' 1 - cos
    for (std::size_t j = 0; j < kLanes; ++j) total += s.solid_angle[j];
    total *= kTwoPi;
    const float scale = options.solid_angle_ratio && total > kTwoPi ? kTwoPi / total : 1.0f;
    float factor[16];
    coefficient_factors(log_eps, factor);
    for (std::size_t i = 0; i < 16; ++i) {
        float sum = 0.0f;
        for (std::size_t j = 0; j < kLanes; ++j) sum += s.f[i][j];
        out[i] += scale * factor[i] * sum;
    }
}

}  // namespace ts::blockers
