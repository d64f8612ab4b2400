#include "core/blockers/projected_cover_share.hpp"

#include <cstddef>

namespace ts::blockers {

std::vector<float> projected_cover_share(const std::vector<FlatSphereNode>& nodes, int samples) {
    std::vector<float> share(nodes.size(), 1.0f);
    std::vector<const Sphere*> leaves;
    for (std::size_t j = 0; j < nodes.size(); ++j) {
        const FlatSphereNode& node = nodes[j];
        if (node.sphere >= 0 || !(node.bound.radius > 0)) continue;
        leaves.clear();
        for (std::size_t k = j + 1; k < std::size_t(node.skip) && k < nodes.size(); ++k)
            if (nodes[k].sphere >= 0) leaves.push_back(&nodes[k].bound);
        const double r = node.bound.radius;
        std::size_t inside = 0, covered = 0;
        for (int a = 0; a < samples; ++a)
            for (int b = 0; b < samples; ++b) {
                const double x = node.bound.center.x + r * (2.0 * (a + 0.5) / samples - 1.0);
                const double y = node.bound.center.y + r * (2.0 * (b + 0.5) / samples - 1.0);
                const double ox = x - node.bound.center.x, oy = y - node.bound.center.y;
                if (ox * ox + oy * oy > r * r) continue;
                ++inside;
                for (const Sphere* s : leaves) {
                    const double dx = x - s->center.x, dy = y - s->center.y;
                    if (dx * dx + dy * dy < s->radius * s->radius) {
                        ++covered;
                        break;
                    }
                }
            }
        if (inside > 0) share[j] = float(double(covered) / double(inside));
    }
    return share;
}

}  // namespace ts::blockers
