#include "core/blockers/self_sky_shadow.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/blockers/sphere_occlusion_shared.hpp"

namespace ts::blockers {

double self_sky_share(const std::vector<FlatSphereNode>& nodes, const std::vector<float>& far_share,
                      const glm::dvec3& point, const glm::dvec3& normal, double detail) {
    double product = 1.0;
    const int count = int(nodes.size());
    for (int i = 0; i < count;) {
        const FlatSphereNode& node = nodes[std::size_t(i)];
        const glm::dvec3 v = node.bound.center - point;
        const double r = node.bound.radius;
        const double hold = r * 1.001 + 0.005;
        const bool holds = glm::dot(v, v) <= hold * hold;
        bool open = false;
        if (node.sphere >= 0) {
            if (!holds && glm::dot(v, normal) > 0.0) {
                const double t = std::clamp((glm::length(v) - r) / r, 0.0, 1.0);
                const double fade = t * t * (3.0 - 2.0 * t);  // smoothstep
                product = shared::ts_sky_cover_step(
                    product, fade * shared::ts_sphere_sky_cover(node.bound.center, r, point, normal), 1.0);
            }
        } else if (holds) {
            open = true;
        } else {
            const double c = shared::ts_sphere_sky_cover(node.bound.center, r, point, normal);
            if (c > detail) open = true;
            else if (c > 0.0) product = shared::ts_sky_cover_step(product, c * double(far_share[std::size_t(i)]), 1.0);
        }
        i = open ? i + 1 : node.skip;
    }
    return product;
}

}  // namespace ts::blockers
