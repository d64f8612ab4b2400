#include "core/blockers/sun_disc_samples.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/util/unit_frame.hpp"

namespace ts::blockers {

std::vector<glm::dvec3> sun_disc_directions(const glm::dvec3& sun, double radius, int count) {
    glm::dvec3 e1, e2;
    unit_frame(sun, e1, e2);
    const int m = std::max(1, count);
    std::vector<glm::dvec3> dirs;
    dirs.reserve(std::size_t(m));
    constexpr double kGoldenAngle = 2.399963229728653;
    for (int i = 0; i < m; ++i) {
        const double rho = radius * std::sqrt((i + 0.5) / m), a = i * kGoldenAngle;
        dirs.push_back(glm::normalize(sun + std::tan(rho) * (std::cos(a) * e1 + std::sin(a) * e2)));
    }
    return dirs;
}

}  // namespace ts::blockers
