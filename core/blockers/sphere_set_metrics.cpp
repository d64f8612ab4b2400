#include "core/blockers/sphere_set_metrics.hpp"

#include <atomic>
#include <random>

#include "core/blockers/sphere_grid.hpp"
#include "core/util/parallel_for.hpp"

namespace ts::blockers {

double surface_coverage(std::span<const Sphere> spheres, std::span<const glm::dvec3> points, int threads) {
    if (points.empty()) return 1.0;
    const SphereGrid grid(spheres);
    const int workers = thread_count(threads);
    const int bands = 8 * workers;
    std::atomic<long long> inside{0};
    parallel_for(bands, workers, [&](int band, int) {
        const std::size_t b0 = points.size() * std::size_t(band) / std::size_t(bands);
        const std::size_t b1 = points.size() * std::size_t(band + 1) / std::size_t(bands);
        long long n = 0;
        for (std::size_t i = b0; i < b1; ++i) n += grid.contains(points[i]);
        inside += n;
    });
    return double(inside.load()) / double(points.size());
}

double excess_volume_ratio(std::span<const Sphere> spheres, const VoxelSolid& solid, int samples, std::uint64_t seed,
                           int threads) {
    const double solid_volume = solid.solid_volume();
    if (spheres.empty() || samples <= 0 || !(solid_volume > 0.0)) return 0.0;
    const SphereGrid grid(spheres);
    const glm::dvec3 lo = grid.lo(), size = grid.hi() - grid.lo();
    const int workers = thread_count(threads);
    const int bands = 8 * workers;
    std::atomic<long long> outside{0};
    parallel_for(bands, workers, [&](int band, int) {
        std::mt19937_64 rng(seed * 1000003ull + std::uint64_t(band));
        std::uniform_real_distribution<double> u(0.0, 1.0);
        const int n = int((long long)samples * (band + 1) / bands - (long long)samples * band / bands);
        long long count = 0;
        for (int i = 0; i < n; ++i) {
            const glm::dvec3 p = lo + glm::dvec3(u(rng), u(rng), u(rng)) * size;
            if (grid.contains(p) && !solid.solid_at(p)) ++count;
        }
        outside += count;
    });
    const double box_volume = size.x * size.y * size.z;
    return double(outside.load()) / double(samples) * box_volume / solid_volume;
}

}  // namespace ts::blockers
