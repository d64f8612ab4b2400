// The gather's chunk march (TerrainGatherer::gather_chunk, 8 receivers in vector lanes) against
// its scalar march (gather()), receiver by receiver: the same sums, far weights and recorded
// texels (with their factors) to float rounding, on hills with voids, at the grid's edges and in rows that end partway
// through a chunk.
#include "core/visibility/terrain_gather.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "core/terrain/terrain_normals.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "tests/visibility/synthetic_terrain.hpp"

namespace ts::visibility {
namespace {

void expect_chunks_match_receivers(int width, int height, const TerrainGatherSettings& settings) {
    SCOPED_TRACE(std::to_string(width) + " x " + std::to_string(height) + ", radius " +
                 std::to_string(settings.radius_texels));
    testing::Terrain t = testing::make_terrain(width, height, 90, 90, testing::hills);
    const std::size_t n = t.z.size();
    // Voids: their own texels and the samples next to them are skipped.
    for (std::size_t k : {std::size_t(3 * width + 5), std::size_t(10 * width + 17), n - 2}) t.z[k] = NAN;
    HorizonOptions o;
    o.directions = 32;
    o.curvature = false;
    const HorizonSet horizons = compute_horizons(t.grid, o);
    const render::NormalField normals = render::terrain_normals(t.grid);
    // Three channels that vary by texel; a patch without values (its weight is far weight).
    constexpr int kChannels = 3;
    std::vector<float> values(n * kChannels);
    for (std::size_t k = 0; k < n; ++k)
        for (int q = 0; q < kChannels; ++q)
            values[k * kChannels + std::size_t(q)] = float(1 + q + std::sin(0.3 * double(k)));
    for (int r = 20; r < 24; ++r)
        for (int c = 30; c < 34 && c < width; ++c) values[std::size_t(r * width + c) * kChannels] = NAN;
    TerrainGatherInputs in;
    in.grid = &t.grid;
    in.horizons = &horizons;
    in.normals = &normals;
    in.channels = kChannels;
    in.values = values;
    // Recorded weights times a per-texel factor (the bounce's albedo).
    std::vector<float> scale(n);
    for (std::size_t k = 0; k < n; ++k) scale[k] = float(0.2 + 0.1 * std::cos(0.05 * double(k)));
    in.record_scale = scale;
    TerrainGatherer scalar(in, settings), lanes(in, settings);
    scalar.set_recording(true);
    lanes.set_recording(true);
    int receivers = 0, with_terrain = 0;
    for (int row = 0; row < height; ++row) {
        scalar.set_row(row);
        lanes.set_row(row);
        for (int col0 = 0; col0 < width; col0 += TerrainGatherer::kChunkLanes) {
            unsigned mask = 0;
            for (int l = 0; l < TerrainGatherer::kChunkLanes && col0 + l < width; ++l)
                if (!std::isnan(t.z[std::size_t(row * width + col0 + l)]) && (l + row) % 5 != 0) mask |= 1u << l;
            lanes.gather_chunk(col0, row, mask);
            // Per lane: the recorded steps' weights by texel.
            std::vector<std::map<long long, double>> by_texel(TerrainGatherer::kChunkLanes);
            for (const TerrainGatherer::StepWeights& sw : lanes.chunk_steps()) {
                const TerrainGatherer::Offset at = lanes.step_texel(sw.step);
                for (int l = 0; l < TerrainGatherer::kChunkLanes; ++l) {
                    if (sw.weight[l] == 0.0f) continue;
                    ASSERT_TRUE(mask >> l & 1u) << "a weight for a receiver left out";
                    by_texel[std::size_t(l)][(long long)(row + at.row) * width + col0 + l + at.col] += sw.weight[l];
                }
            }
            for (int l = 0; l < TerrainGatherer::kChunkLanes; ++l) {
                if (!(mask >> l & 1u)) continue;
                SCOPED_TRACE("receiver " + std::to_string(col0 + l) + ", " + std::to_string(row));
                ++receivers;
                scalar.gather(col0 + l, row);
                // Weights are differences of F, in [0, ~pi/2]: float rounding of ~1e-6 each.
                const double tol = 2e-5 * (1 + scalar.seen_weight() + scalar.far_weight());
                EXPECT_NEAR(lanes.chunk_far_weight(l), scalar.far_weight(), tol);
                for (int q = 0; q < kChannels; ++q)
                    EXPECT_NEAR(lanes.chunk_seen(l)[q], scalar.seen()[std::size_t(q)], tol * (3 + 1));
                std::map<long long, double> expected;
                for (std::size_t k = 0; k < scalar.seen_texels().size(); ++k)
                    expected[scalar.seen_texels()[k]] += scalar.seen_weights()[k];
                with_terrain += !expected.empty();
                for (const auto& [texel, weight] : expected)
                    EXPECT_NEAR(by_texel[std::size_t(l)][texel], weight, tol) << "texel " << texel;
                // (A sample within rounding of the last maximum may rise in one march only.)
                for (const auto& [texel, weight] : by_texel[std::size_t(l)]) {
                    if (!expected.count(texel)) {
                        EXPECT_LT(weight, tol) << "texel " << texel << " only in the chunk's";
                    }
                }
            }
        }
    }
    EXPECT_GT(with_terrain, receivers / 2);  // the hills are seen
}

TEST(TerrainGatherer, ItsChunkMarchIsItsScalarMarch) {
    TerrainGatherSettings s;
    s.directions = 8;
    s.radius_texels = 32;
    expect_chunks_match_receivers(48, 40, s);
    expect_chunks_match_receivers(45, 30, s);  // rows ending partway through a chunk
    s.directions = 16;
    s.radius_texels = 12;
    s.growth = 1.5;
    expect_chunks_match_receivers(37, 25, s);
}

}  // namespace
}  // namespace ts::visibility
