#include "core/sh/log_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "core/sh/sh_shared.hpp"
#include "core/sh/slice_projector.hpp"
#include "core/util/angles.hpp"

namespace ts::sh {

std::uint64_t SplitMix64::next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double SplitMix64::uniform() {
    return static_cast<double>(next() >> 11) * 0x1.0p-53;
}

LogScene random_scene(const SceneOptions& o, SplitMix64& rng) {
    LogScene scene;
    scene.log_eps = o.log_eps;
    for (int b = 0; b < o.blockers; ++b) {
        // Uniform direction on the upper hemisphere.
        const double z = rng.uniform();
        const double phi = rng.uniform(0.0, 2.0 * kPi);
        const double r = std::sqrt(1.0 - z * z);
        const double tb = radians(rng.uniform(o.min_theta_b_deg, o.max_theta_b_deg));
        scene.caps.push_back({glm::dvec3(r * std::cos(phi), r * std::sin(phi), z), tb});
    }
    if (o.height_field) {
        scene.horizons.resize(o.slices);
        const double base = rng.uniform(-5.0, 20.0);
        const double amp = rng.uniform(0.0, 20.0);
        const double phase = rng.uniform(0.0, 2.0 * kPi);
        for (int k = 0; k < o.slices; ++k) {
            const double phi = SliceProjector::azimuth(k, o.slices);
            const double s = base + amp * std::sin(phi + phase) + rng.uniform(-5.0, 5.0);
            scene.horizons[k] = static_cast<float>(radians(std::clamp(s, -89.0, 89.0)));
        }
    }
    return scene;
}

ShVec LogScene::log_sh() const {
    ShVec f{};
    for (const Cap& c : caps) {
        // A cap's log-ZH straight from the shared formula (core/blockers/sphere_blocker.hpp wraps
        // the same one; ts_sh cannot depend on ts_blockers, which depends on ts_sh).
        double zh[kBands];
        shared::ts_sphere_log_zh(c.theta_b, log_eps, zh);
        f = f + zh_rotate({zh[0], zh[1], zh[2], zh[3]}, c.axis);
    }
    if (!horizons.empty()) {
        const SliceProjector projector(static_cast<int>(horizons.size()));
        const auto hf = projector.project_horizons(horizons.data(), static_cast<float>(log_eps));
        for (int i = 0; i < kCount; ++i) f[i] += hf[i];
    }
    return f;
}

double LogScene::true_log(const glm::dvec3& d) const {
    double v = 0.0;
    for (const Cap& c : caps)
        if (glm::dot(d, c.axis) >= std::cos(c.theta_b)) v += log_eps;
    if (!horizons.empty()) {
        const int n = static_cast<int>(horizons.size());
        double phi = std::atan2(d.y, d.x);
        if (phi < 0.0) phi += 2.0 * kPi;
        const double x = phi / (2.0 * kPi) * n;
        const int k = std::min(static_cast<int>(x), n - 1);
        const double t = x - k;
        const double elevation = std::asin(std::clamp(d.z, -1.0, 1.0));
        const double below_k = elevation <= horizons[k] ? 1.0 : 0.0;
        const double below_k1 = elevation <= horizons[(k + 1) % n] ? 1.0 : 0.0;
        v += log_eps * ((1.0 - t) * below_k + t * below_k1);
    }
    return v;
}

ShVec random_visibility_log(const SceneOptions& o, SplitMix64& rng) {
    return random_scene(o, rng).log_sh();
}

ShVec random_log_shape(SplitMix64& rng) {
    for (;;) {
        SceneOptions o;
        o.blockers = 1 + static_cast<int>(rng.next() % 16);
        o.height_field = rng.uniform() < 0.5;
        ShVec f = random_visibility_log(o, rng);
        f[0] = 0.0;
        const double n = norm(f);
        if (n > 1e-9) return (1.0 / n) * f;
    }
}

}  // namespace ts::sh
