#include "core/blockers/sphere_fit.hpp"

#include <cmath>
#include <random>

#include "core/blockers/minimal_enclosing_sphere.hpp"
#include "core/util/angles.hpp"

namespace ts::blockers {

OutsideVolume::OutsideVolume(const VoxelSolid& solid, int samples) : solid_(solid) {
    std::mt19937_64 rng(0xba11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    while (int(unit_ball_.size()) < samples) {
        const glm::dvec3 p(u(rng), u(rng), u(rng));
        if (p.x * p.x + p.y * p.y + p.z * p.z <= 1.0) unit_ball_.push_back(p);
    }
}

double OutsideVolume::operator()(const Sphere& s) const {
    int out = 0;
    for (const glm::dvec3& p : unit_ball_)
        if (!solid_.solid_at(s.center + s.radius * p)) ++out;
    return 4.0 / 3.0 * kPi * s.radius * s.radius * s.radius * double(out) / double(unit_ball_.size());
}

double fit_cost(const Sphere& s, const OutsideVolume& outside) {
    constexpr double kVolumeWeight = 0.05;
    return outside(s) + kVolumeWeight * 4.0 / 3.0 * kPi * s.radius * s.radius * s.radius;
}

Sphere fit_bounding_sphere(std::span<const glm::dvec3> points, const glm::dvec3& interior, const OutsideVolume& outside) {
    Sphere best = minimal_enclosing_sphere(points);
    if (points.size() < 2) return best;
    double best_cost = fit_cost(best, outside);
    auto try_center = [&](const glm::dvec3& c) {
        const Sphere s{c, enclosing_radius(points, c)};
        const double cost = fit_cost(s, outside);
        if (cost < best_cost) {
            best = s;
            best_cost = cost;
            return true;
        }
        return false;
    };
    // 1. Along the line from the minimal sphere's centre to the interior point.
    const glm::dvec3 c0 = best.center;
    for (double t : {0.25, 0.5, 0.75, 1.0, 1.5}) try_center(c0 + t * (interior - c0));
    // 2. A compass search around the best centre: steps along the axes, halved when none helps.
    double step = 0.25 * best.radius;
    const glm::dvec3 dirs[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int round = 0; round < 12 && step > 0.02 * best.radius; ++round) {
        bool moved = false;
        for (const glm::dvec3& d : dirs) moved |= try_center(best.center + step * d);
        if (!moved) step *= 0.5;
    }
    return best;
}

}  // namespace ts::blockers
