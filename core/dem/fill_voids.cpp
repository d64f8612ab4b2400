#include "core/dem/fill_voids.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/util/error.hpp"

namespace ts::dem {

namespace {
// Relaxation: over-relaxation factor for Gauss-Seidel on the Laplace equation (1.8 converges
// far faster than 1.0 on holes tens of cells wide), stop when no cell moves by a millimetre,
// at most 500 sweeps and about 2e8 cell updates in all so a huge hole stays a few seconds.
constexpr double kOverRelaxation = 1.8;
constexpr double kConvergedMetres = 1e-3;
constexpr std::size_t kMaxSweeps = 500;
constexpr std::size_t kRelaxationBudget = 200'000'000;

enum Mark : std::uint8_t { kData = 0, kVoid = 1, kOutside = 2, kHole = 3 };

// The voids split by kind: one byte per texel (Mark), the outside's texels and each hole's.
struct VoidRegions {
    std::vector<std::uint8_t> mark;
    std::vector<std::size_t> voids;  // every void texel, in index order
    std::size_t outside = 0;
    std::vector<std::vector<std::size_t>> holes;
    std::size_t visited = 0;
};

bool is_void_at(const Dem& dem, std::size_t i) {
    return (!dem.void_mask.empty() && dem.void_mask[i]) || std::isnan(dem.z[i]);
}

// One linear scan marks the voids; then a 4-connected flood from the border's voids marks the
// outside and a 4-connected labelling of what is left gives the holes. Both visit void texels only.
VoidRegions find_void_regions(const Dem& dem) {
    const int w = dem.width, h = dem.height;
    VoidRegions v;
    v.mark.assign(dem.z.size(), kData);
    for (std::size_t i = 0; i < dem.z.size(); ++i)
        if (is_void_at(dem, i)) {
            v.mark[i] = kVoid;
            v.voids.push_back(i);
        }
    if (v.voids.empty()) return v;

    std::vector<std::size_t> queue;
    auto flood = [&](std::size_t seed, Mark as) {  // 4-connected, from an unvisited void
        queue.clear();
        v.mark[seed] = as;
        queue.push_back(seed);
        for (std::size_t head = 0; head < queue.size(); ++head) {
            const std::size_t i = queue[head];
            ++v.visited;
            const int c = int(i % std::size_t(w)), r = int(i / std::size_t(w));
            for (auto [dc, dr] : {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}}) {
                const int cc = c + dc, rr = r + dr;
                if (cc < 0 || cc >= w || rr < 0 || rr >= h) continue;
                const std::size_t n = dem.index(cc, rr);
                if (v.mark[n] == kVoid) {
                    v.mark[n] = as;
                    queue.push_back(n);
                }
            }
        }
    };
    auto seed_outside = [&](int c, int r) {
        const std::size_t i = dem.index(c, r);
        if (v.mark[i] == kVoid) {
            flood(i, kOutside);
            v.outside += queue.size();
        }
    };
    for (int c = 0; c < w; ++c) seed_outside(c, 0), seed_outside(c, h - 1);
    for (int r = 0; r < h; ++r) seed_outside(0, r), seed_outside(w - 1, r);
    for (std::size_t i : v.voids)
        if (v.mark[i] == kVoid) {
            flood(i, kHole);
            v.holes.push_back(queue);
        }
    return v;
}

// Fills one hole in its bounding box (grown by one texel for its rim) if every texel is within
// max_distance of the rim; returns false, leaving it NaN, if not.
bool fill_hole(Dem& dem, const std::vector<std::uint8_t>& mark, const std::vector<std::size_t>& hole,
               int max_distance, int sweeps, std::size_t& visited) {
    const int w = dem.width;
    int c0 = w, c1 = -1, r0 = dem.height, r1 = -1;
    for (std::size_t i : hole) {
        const int c = int(i % std::size_t(w)), r = int(i / std::size_t(w));
        c0 = std::min(c0, c), c1 = std::max(c1, c), r0 = std::min(r0, r), r1 = std::max(r1, r);
    }
    // A hole never touches the border (it would be outside), so its box grown by one is in the grid.
    c0 -= 1, r0 -= 1, c1 += 1, r1 += 1;
    const int bw = c1 - c0 + 1;
    constexpr int kUnset = std::numeric_limits<int>::max();
    std::vector<int> layer(std::size_t(bw) * std::size_t(r1 - r0 + 1), kUnset);
    auto local = [&](std::size_t i) {
        return std::size_t(int(i / std::size_t(w)) - r0) * std::size_t(bw) + std::size_t(int(i % std::size_t(w)) - c0);
    };
    auto for_neighbours = [&](std::size_t i, auto&& visit) {
        const int c = int(i % std::size_t(w)), r = int(i / std::size_t(w));
        for (int dr = -1; dr <= 1; ++dr)
            for (int dc = -1; dc <= 1; ++dc)
                if (dc || dr) visit(dem.index(c + dc, r + dr));
    };

    // Multi-source breadth-first search from the rim gives each texel its layer (8-neighbour
    // distance to a measured texel, through the hole); filling in that order keeps the peel
    // linear in the hole's size.
    std::vector<std::size_t> queue;
    queue.reserve(hole.size());
    for (std::size_t i : hole) layer[local(i)] = -1;  // -1: in the hole, not reached yet
    auto in_this_hole = [&](std::size_t n) { return mark[n] == kHole && layer[local(n)] != kUnset; };
    for (std::size_t i : hole) {
        bool rim = false;
        for_neighbours(i, [&](std::size_t n) { rim = rim || mark[n] == kData; });
        if (rim) {
            layer[local(i)] = 1;
            queue.push_back(i);
        }
    }
    int deepest = 0;
    for (std::size_t head = 0; head < queue.size(); ++head) {
        ++visited;
        const int here = layer[local(queue[head])];
        deepest = std::max(deepest, here);
        for_neighbours(queue[head], [&](std::size_t n) {
            if (in_this_hole(n) && layer[local(n)] == -1) {
                layer[local(n)] = here + 1;
                queue.push_back(n);
            }
        });
    }
    if (deepest > max_distance) return false;

    // Queue order is layer order: each texel takes the mean of its neighbours from inner layers
    // (measured texels are layer 0; another void's texels are not read).
    for (std::size_t i : queue) {
        const int here = layer[local(i)];
        double sum = 0;
        int n = 0;
        for_neighbours(i, [&](std::size_t nb) {
            if (mark[nb] == kData || (in_this_hole(nb) && layer[local(nb)] < here)) {
                sum += dem.z[nb];
                ++n;
            }
        });
        dem.z[i] = float(sum / n);  // n >= 1: the BFS reached i from a lower layer
    }

    // Relax the hole's texels towards the harmonic surface their rim defines (Laplace equation,
    // successive over-relaxation), measured texels fixed: the peel's rings vanish and a hole in
    // a plane fills as that plane. A 4-neighbour of a hole texel is measured or in the same
    // hole (the hole is 4-connected), and inside the grid.
    for (int sweep = 0; sweep < sweeps; ++sweep) {
        double largest_change = 0;
        for (std::size_t i : queue) {
            ++visited;
            const int c = int(i % std::size_t(w)), r = int(i / std::size_t(w));
            const double sum = double(dem.z[dem.index(c - 1, r)]) + dem.z[dem.index(c + 1, r)] +
                               dem.z[dem.index(c, r - 1)] + dem.z[dem.index(c, r + 1)];
            const double change = kOverRelaxation * (sum / 4 - dem.z[i]);
            dem.z[i] = float(dem.z[i] + change);
            largest_change = std::max(largest_change, std::abs(change));
        }
        if (largest_change < kConvergedMetres) break;
    }
    return true;
}

}  // namespace

VoidFillStats fill_voids(Dem& dem, const VoidFillOptions& options) {
    VoidFillStats stats;
    if (dem.void_mask.size() != dem.z.size()) dem.void_mask.resize(dem.z.size(), 0);
    const VoidRegions regions = find_void_regions(dem);
    if (regions.voids.empty()) return stats;
    if (regions.voids.size() == dem.z.size()) throw input_error(dem.source, "no valid height anywhere (all cells are nodata)");
    stats.visited = regions.visited;
    stats.outside_texels = regions.outside;
    // Every void is NaN with its mask set until a hole is filled.
    for (std::size_t i : regions.voids) dem.void_mask[i] = 1, dem.z[i] = std::numeric_limits<float>::quiet_NaN();

    std::size_t hole_texels = 0;
    for (const auto& hole : regions.holes) hole_texels += hole.size();
    const std::size_t budget = kRelaxationBudget / std::max<std::size_t>(hole_texels, 1);
    const int sweeps = int(std::min<std::size_t>(kMaxSweeps, std::max<std::size_t>(budget, 1)));
    for (const auto& hole : regions.holes) {
        if (fill_hole(dem, regions.mark, hole, options.max_distance, sweeps, stats.visited)) {
            stats.filled_texels += hole.size();
            ++stats.holes_filled;
        } else {
            stats.unfilled_texels += hole.size();
            ++stats.holes_unfilled;
        }
    }
    return stats;
}

std::size_t floor_outside(Dem& dem) {
    float lowest = std::numeric_limits<float>::infinity();
    std::size_t outside = 0;
    for (float z : dem.z) {
        if (std::isnan(z)) ++outside;
        else lowest = std::min(lowest, z);
    }
    if (outside == 0 || !std::isfinite(lowest)) return 0;
    if (dem.void_mask.size() != dem.z.size()) dem.void_mask.resize(dem.z.size(), 0);
    for (std::size_t i = 0; i < dem.z.size(); ++i)
        if (std::isnan(dem.z[i])) dem.z[i] = lowest, dem.void_mask[i] = 1;
    return outside;
}

VoidKinds classify_voids(const Dem& dem) {
    const VoidRegions regions = find_void_regions(dem);
    VoidKinds k;
    k.outside_texels = regions.outside;
    k.hole_texels = regions.voids.size() - regions.outside;
    k.holes = regions.holes.size();
    return k;
}

}  // namespace ts::dem
