#pragma once
// The sphere blockers' log-SH accumulation as a kernel: for one receiver, the sum over a set of
// spheres of their caps' log-SH (sh_shared.h's ts_sphere_log_zh_rd and ts_zh_rotate), with the
// ratio attenuation of sphere_blocker.hpp (caps wholly below the tangent plane dropped, the
// sum scaled to claim at most the upper hemisphere), in single precision as the GPU computes
// it, vectorised across spheres (AVX-512, AVX2 or baseline x86-64, picked at load time).
// accumulate_blockers (sphere_blocker.hpp) is the double-precision reference it is tested
// against.
#include <cstddef>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/blockers/sphere_blocker.hpp"

namespace ts::blockers {

// Spheres as lanes of floats (structure of arrays), padded to whole groups of kLanes (the
// kernel skips the padding).
class SphereLanes {
public:
    static constexpr std::size_t kLanes = 16;

    SphereLanes() = default;
    explicit SphereLanes(std::span<const Sphere> spheres) { assign(spheres); }

    void assign(std::span<const Sphere> spheres);
    void clear();
    void push_back(const Sphere& s) {
        if (count_ == x_.size()) grow();
        x_[count_] = float(s.center.x), y_[count_] = float(s.center.y), z_[count_] = float(s.center.z);
        r_[count_] = float(s.radius);
        ++count_;
    }
    std::size_t size() const { return count_; }
    bool empty() const { return count_ == 0; }
    // Lanes allocated: size() rounded up to kLanes.
    std::size_t padded() const { return x_.size(); }
    const float* x() const { return x_.data(); }
    const float* y() const { return y_.data(); }
    const float* z() const { return z_.data(); }
    const float* radius() const { return r_.data(); }

private:
    void grow();  // one more group of lanes
    std::vector<float> x_, y_, z_, r_;
    std::size_t count_ = 0;
};

// Sum over the spheres (centres in any frame) of their log-SH seen from `receiver` (the same
// frame), each kept only when its cap reaches above the plane of unit `normal`
// (options.cull_lower_hemisphere), the sum scaled by 2 pi / (sum of kept caps' solid angles)
// when that exceeds 2 pi (options.solid_angle_ratio). Adds the 16 coefficients to `out`.
void accumulate_sphere_lanes(const SphereLanes& spheres, const glm::vec3& receiver, const glm::vec3& normal,
                             float log_eps, const RatioAttenuation& options, float out[16]);

}  // namespace ts::blockers
