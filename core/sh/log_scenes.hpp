#pragma once
// Random log-visibility vectors for the exponentiation benchmark, the optimal-linear fit and
// the tests: sums of sphere blockers (upper hemisphere, random size) and optionally a height
// field with random horizons. A fixed-seed SplitMix64 keeps every run reproducible on every
// platform (std:: distributions are not portable).
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "core/sh/sh_basis.hpp"

namespace ts::sh {

class SplitMix64 {
public:
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next();
    double uniform();  // [0, 1)
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

private:
    std::uint64_t state_;
};

struct SceneOptions {
    int blockers = 0;
    bool height_field = false;
    double log_eps = -6.907755278982137;  // log(0.001)
    double min_theta_b_deg = 2.0;
    double max_theta_b_deg = 20.0;
    int slices = 32;
};

// A random scene: its blockers' caps and height-field horizons, from which both the log-SH
// vector (the method's input) and the true log-visibility at any direction follow.
struct LogScene {
    struct Cap {
        glm::dvec3 axis;
        double theta_b;
    };
    std::vector<Cap> caps;
    std::vector<float> horizons;  // empty: no height field; else slice k at azimuth 2 pi k / D
    double log_eps = 0.0;

    ShVec log_sh() const;
    // The un-truncated log-visibility: log_eps per covering cap, plus the height field's
    // log-visibility blended linearly in azimuth between slices (the SliceProjector model).
    double true_log(const glm::dvec3& d) const;
};

LogScene random_scene(const SceneOptions& options, SplitMix64& rng);
ShVec random_visibility_log(const SceneOptions& options, SplitMix64& rng);

// A DC-free unit-norm shape drawn from the same scenes (1..16 blockers, height field half the
// time): what the optimal-linear coefficients are fitted on.
ShVec random_log_shape(SplitMix64& rng);

}  // namespace ts::sh
