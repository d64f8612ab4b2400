#include "core/mesh/surface_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace ts::mesh {

std::vector<glm::dvec3> sample_surface(const TriangleMesh& mesh, int count, std::uint64_t seed) {
    const std::size_t n = mesh.triangle_count();
    std::vector<double> cumulative(n);
    double total = 0.0;
    for (std::size_t t = 0; t < n; ++t) {
        total += triangle_area(mesh.positions[3 * t], mesh.positions[3 * t + 1], mesh.positions[3 * t + 2]);
        cumulative[t] = total;
    }
    std::vector<glm::dvec3> out;
    if (n == 0 || count <= 0 || !(total > 0.0)) return out;
    out.reserve(std::size_t(count));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < count; ++i) {
        const double pick = u(rng) * total;
        const std::size_t t = std::min<std::size_t>(
            std::size_t(std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin()), n - 1);
        // Uniform on the triangle: the square-root warp of two uniforms.
        const double s = std::sqrt(u(rng)), v = u(rng);
        const glm::dvec3 a(mesh.positions[3 * t]), b(mesh.positions[3 * t + 1]), c(mesh.positions[3 * t + 2]);
        out.push_back((1.0 - s) * a + s * (1.0 - v) * b + s * v * c);
    }
    return out;
}

}  // namespace ts::mesh
