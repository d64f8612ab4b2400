#include "core/blockers/solid_clustering.hpp"

#include <algorithm>
#include <limits>
#include <random>

#include <glm/geometric.hpp>

#include "core/util/parallel_for.hpp"

namespace ts::blockers {

namespace {

double dist2(const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 d = a - b;
    return glm::dot(d, d);
}

int nearest(const std::vector<glm::dvec3>& centers, const glm::dvec3& p) {
    int best = 0;
    double best_d = std::numeric_limits<double>::max();
    for (int c = 0; c < int(centers.size()); ++c) {
        const double d = dist2(centers[std::size_t(c)], p);
        if (d < best_d) {
            best_d = d;
            best = c;
        }
    }
    return best;
}

}  // namespace

SolidClustering cluster_solid(const VoxelSolid& solid, const ClusteringOptions& o) {
    std::mt19937_64 rng(o.seed);
    // The points: solid cell centres, subsampled to at most max_points.
    std::vector<glm::dvec3> points;
    std::size_t solid_cells = 0;
    for (VoxelState s : solid.state) solid_cells += s != VoxelState::outside;
    const double keep = std::min(1.0, double(o.max_points) / double(std::max<std::size_t>(solid_cells, 1)));
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int c = 0; c < int(solid.state.size()); ++c)
        if (solid.state[std::size_t(c)] != VoxelState::outside && u(rng) < keep) points.push_back(solid.cell_center(c));
    if (points.empty())
        for (int c : solid.surface_cells) points.push_back(solid.cell_center(c));

    const int k = std::max(1, o.count);
    const int workers = thread_count(o.threads);
    SolidClustering out;
    // k-means++: each new seed drawn with probability proportional to the squared distance to
    // the nearest seed so far.
    std::vector<double> d2(points.size(), std::numeric_limits<double>::max());
    out.centers.push_back(points[std::size_t(rng() % points.size())]);
    while (int(out.centers.size()) < k) {
        double total = 0.0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            d2[i] = std::min(d2[i], dist2(points[i], out.centers.back()));
            total += d2[i];
        }
        if (!(total > 0.0)) {  // fewer distinct points than clusters
            out.centers.push_back(points[std::size_t(rng() % points.size())]);
            continue;
        }
        double pick = u(rng) * total;
        std::size_t chosen = points.size() - 1;
        for (std::size_t i = 0; i < points.size(); ++i) {
            pick -= d2[i];
            if (pick <= 0.0) {
                chosen = i;
                break;
            }
        }
        out.centers.push_back(points[chosen]);
    }
    // Lloyd: assign (in parallel bands), then move each centre to its members' mean.
    std::vector<int> label(points.size(), 0);
    const int bands = 8 * workers;
    for (int it = 0; it < o.iterations; ++it) {
        parallel_for(bands, workers, [&](int band, int) {
            const std::size_t b0 = points.size() * std::size_t(band) / std::size_t(bands);
            const std::size_t b1 = points.size() * std::size_t(band + 1) / std::size_t(bands);
            for (std::size_t i = b0; i < b1; ++i) label[i] = nearest(out.centers, points[i]);
        });
        std::vector<glm::dvec3> sum(std::size_t(k), glm::dvec3(0.0));
        std::vector<int> n(std::size_t(k), 0);
        for (std::size_t i = 0; i < points.size(); ++i) {
            sum[std::size_t(label[i])] += points[i];
            ++n[std::size_t(label[i])];
        }
        for (int c = 0; c < k; ++c)
            if (n[std::size_t(c)] > 0) out.centers[std::size_t(c)] = sum[std::size_t(c)] / double(n[std::size_t(c)]);
    }
    const int surface = int(solid.surface_cells.size());
    out.surface_cluster.resize(std::size_t(surface));
    parallel_for(bands, workers, [&](int band, int) {
        const int s0 = int((long long)surface * band / bands), s1 = int((long long)surface * (band + 1) / bands);
        for (int s = s0; s < s1; ++s)
            out.surface_cluster[std::size_t(s)] = nearest(out.centers, solid.cell_center(solid.surface_cells[std::size_t(s)]));
    });
    return out;
}

}  // namespace ts::blockers
