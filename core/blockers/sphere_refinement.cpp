#include "core/blockers/sphere_refinement.hpp"

#include <algorithm>
#include <numeric>

#include <glm/common.hpp>

namespace ts::blockers {

namespace {

bool is_free(const Sphere& s) { return !(s.radius > 0.0); }

// Splits cells in two halves at the median of their centres along their box's longest side.
std::pair<std::vector<int>, std::vector<int>> split_cells(const SurfaceCover& cover, std::vector<int> cells) {
    glm::dvec3 lo = cover.cell_center(cells[0]), hi = lo;
    for (int e : cells) {
        lo = glm::min(lo, cover.cell_center(e));
        hi = glm::max(hi, cover.cell_center(e));
    }
    const glm::dvec3 size = hi - lo;
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
    const auto mid = cells.begin() + std::ptrdiff_t(cells.size() / 2);
    std::nth_element(cells.begin(), mid, cells.end(),
                     [&](int a, int b) { return cover.cell_center(a)[axis] < cover.cell_center(b)[axis]; });
    return {std::vector<int>(cells.begin(), mid), std::vector<int>(mid, cells.end())};
}

glm::dvec3 mean_center(const SurfaceCover& cover, const std::vector<int>& cells) {
    glm::dvec3 sum(0.0);
    for (int e : cells) sum += cover.cell_center(e);
    return sum / double(cells.size());
}

}  // namespace

void refine_spheres(SurfaceCover& cover, std::vector<Sphere>& spheres, std::vector<glm::dvec3>& interiors,
                    const OutsideVolume& outside, int passes) {
    const int n = int(spheres.size());
    for (const Sphere& s : spheres)
        if (!is_free(s)) cover.count(s, +1);
    std::vector<double> cost(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) cost[std::size_t(i)] = is_free(spheres[std::size_t(i)]) ? 0.0 : fit_cost(spheres[std::size_t(i)], outside);

    // Free spheres go where they help most: the costliest sphere's own cells, split in two.
    auto reuse_free = [&] {
        for (int f = 0; f < n; ++f) {
            if (!is_free(spheres[std::size_t(f)])) continue;
            std::vector<int> by_cost(static_cast<std::size_t>(n));
            std::iota(by_cost.begin(), by_cost.end(), 0);
            std::sort(by_cost.begin(), by_cost.end(), [&](int a, int b) { return cost[std::size_t(a)] > cost[std::size_t(b)]; });
            for (int big : by_cost) {
                if (is_free(spheres[std::size_t(big)])) break;
                std::vector<int> own = cover.held_only_by(spheres[std::size_t(big)]);
                if (own.size() < 2) continue;
                auto [a, b] = split_cells(cover, std::move(own));
                const Sphere sa = fit_bounding_sphere(cover.corners_of(a), interiors[std::size_t(big)], outside);
                const glm::dvec3 ib = mean_center(cover, b);
                const Sphere sb = fit_bounding_sphere(cover.corners_of(b), ib, outside);
                cover.count(spheres[std::size_t(big)], -1);
                spheres[std::size_t(big)] = sa;
                spheres[std::size_t(f)] = sb;
                interiors[std::size_t(f)] = ib;
                cover.count(sa, +1);
                cover.count(sb, +1);
                cost[std::size_t(big)] = fit_cost(sa, outside);
                cost[std::size_t(f)] = fit_cost(sb, outside);
                break;
            }
        }
    };

    reuse_free();
    for (int pass = 0; pass < passes; ++pass) {
        std::vector<int> order(static_cast<std::size_t>(n));
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(), [&](int a, int b) { return cost[std::size_t(a)] > cost[std::size_t(b)]; });
        for (int i : order) {
            Sphere& s = spheres[std::size_t(i)];
            if (is_free(s)) continue;
            const std::vector<int> own = cover.held_only_by(s);
            if (own.empty()) {  // every cell it holds is held by another: drop it, reuse below
                cover.count(s, -1);
                s.radius = 0.0;
                cost[std::size_t(i)] = 0.0;
                continue;
            }
            const Sphere refit = fit_bounding_sphere(cover.corners_of(own), interiors[std::size_t(i)], outside);
            const double refit_cost = fit_cost(refit, outside);
            if (refit_cost < cost[std::size_t(i)]) {
                cover.count(s, -1);
                s = refit;
                cover.count(s, +1);
                cost[std::size_t(i)] = refit_cost;
            }
        }
        reuse_free();
    }
    std::vector<Sphere> kept;
    std::vector<glm::dvec3> kept_interiors;
    for (int i = 0; i < n; ++i)
        if (!is_free(spheres[std::size_t(i)])) {
            kept.push_back(spheres[std::size_t(i)]);
            kept_interiors.push_back(interiors[std::size_t(i)]);
        }
    spheres = std::move(kept);
    interiors = std::move(kept_interiors);
}

}  // namespace ts::blockers
