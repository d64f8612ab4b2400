#include "core/dem/fill_voids.hpp"

#include <algorithm>
#include <cmath>

#include "core/util/error.hpp"

namespace ts::dem {

namespace {
// Relaxation: over-relaxation factor for Gauss-Seidel on the Laplace equation (1.8 converges
// far faster than 1.0 on holes tens of cells wide), stop when no cell moves by a millimetre,
// at most 500 sweeps and about 2e8 cell updates in all so a huge void stays a few seconds.
constexpr double kOverRelaxation = 1.8;
constexpr double kConvergedMetres = 1e-3;
constexpr std::size_t kMaxSweeps = 500;
constexpr std::size_t kRelaxationBudget = 200'000'000;
}  // namespace

void fill_voids(Dem& dem) {
    std::vector<std::size_t> pending;
    for (std::size_t i = 0; i < dem.z.size(); ++i)
        if (dem.void_mask[i] || std::isnan(dem.z[i])) {
            dem.void_mask[i] = 1;
            pending.push_back(i);
        }
    if (pending.empty()) return;
    if (pending.size() == dem.z.size()) throw input_error(dem.source, "no valid height anywhere (all cells are nodata)");

    // Multi-source breadth-first search from the measured cells gives each void its layer
    // (8-neighbour distance to the rim); filling in that order makes the peel O(cells).
    const int w = dem.width, h = dem.height;
    constexpr int kUnset = -1;
    std::vector<int> layer(dem.z.size(), kUnset);
    std::vector<std::size_t> queue;
    queue.reserve(pending.size());
    for (std::size_t i = 0; i < dem.z.size(); ++i)
        if (!dem.void_mask[i]) layer[i] = 0;
    auto for_neighbours = [&](std::size_t i, auto&& visit) {
        const int c = int(i % std::size_t(w)), r = int(i / std::size_t(w));
        for (int dr = -1; dr <= 1; ++dr)
            for (int dc = -1; dc <= 1; ++dc) {
                const int cc = c + dc, rr = r + dr;
                if ((dc || dr) && cc >= 0 && cc < w && rr >= 0 && rr < h) visit(dem.index(cc, rr));
            }
    };
    for (std::size_t i : pending) {  // first layer: voids touching a measured cell
        bool rim = false;
        for_neighbours(i, [&](std::size_t n) { rim = rim || layer[n] == 0; });
        if (rim) {
            layer[i] = 1;
            queue.push_back(i);
        }
    }
    for (std::size_t head = 0; head < queue.size(); ++head)
        for_neighbours(queue[head], [&](std::size_t n) {
            if (layer[n] == kUnset) {
                layer[n] = layer[queue[head]] + 1;
                queue.push_back(n);
            }
        });
    // Queue order is layer order: each void takes the mean of its neighbours from inner layers.
    for (std::size_t i : queue) {
        double sum = 0;
        int n = 0;
        for_neighbours(i, [&](std::size_t nb) {
            if (layer[nb] != kUnset && layer[nb] < layer[i]) {
                sum += dem.z[nb];
                ++n;
            }
        });
        dem.z[i] = float(sum / n);  // n >= 1: the BFS reached i from a lower layer
    }

    // Relax the filled cells towards the harmonic surface their rim defines (Laplace equation,
    // successive over-relaxation), measured cells fixed: the peel's rings vanish and a hole in
    // a plane fills as that plane.
    const std::size_t budget = kRelaxationBudget / std::max<std::size_t>(queue.size(), 1);
    const int sweeps = int(std::min<std::size_t>(kMaxSweeps, std::max<std::size_t>(budget, 1)));
    for (int sweep = 0; sweep < sweeps; ++sweep) {
        double largest_change = 0;
        for (std::size_t i : queue) {
            const int c = int(i % std::size_t(w)), r = int(i / std::size_t(w));
            double sum = 0;
            int n = 0;
            for (auto [dc, dr] : {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}}) {
                const int cc = c + dc, rr = r + dr;
                if (cc >= 0 && cc < w && rr >= 0 && rr < h) {
                    sum += dem.z[dem.index(cc, rr)];
                    ++n;
                }
            }
            const double change = kOverRelaxation * (sum / n - dem.z[i]);
            dem.z[i] = float(dem.z[i] + change);
            largest_change = std::max(largest_change, std::abs(change));
        }
        if (largest_change < kConvergedMetres) break;
    }
}

}  // namespace ts::dem
