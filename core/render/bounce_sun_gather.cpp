#include "core/render/bounce_sun_gather.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "core/util/parallel_for.hpp"

namespace ts::render {
namespace {

// out[t] = base_scale base[t] + sum_j w_tj values[j] over the texels of rows [r0, r1).
void gather_rows(const BounceSunGather& g, const float* values, const float* base, float base_scale, float* out,
                 int r0, int r1) {
    const std::size_t w = std::size_t(g.width);
    const std::ptrdiff_t stride = std::ptrdiff_t(g.width);
    for (int r = r0; r < r1; ++r) {
        const BounceSunGather::Entry* entry = g.rows[std::size_t(r)].data();
        const std::uint32_t row_end = std::uint32_t(g.rows[std::size_t(r)].size());
        const std::size_t t0 = std::size_t(r) * w;
        for (std::size_t c = 0; c < w; ++c) {
            const std::size_t t = t0 + c;
            const std::uint32_t e = c + 1 < w ? g.begin[t + 1] : row_end;
            const float* here = values + t;
            auto term = [&](std::uint32_t k) {
                return float(entry[k].weight) * here[std::ptrdiff_t(entry[k].dr) * stride + entry[k].dc];
            };
            // Four sums: one would wait on each add (the loop is the adds' latency, not the reads).
            float s0 = 0, s1 = 0, s2 = 0, s3 = 0;
            std::uint32_t k = g.begin[t];
            for (; k + 4 <= e; k += 4) s0 += term(k), s1 += term(k + 1), s2 += term(k + 2), s3 += term(k + 3);
            for (; k < e; ++k) s0 += term(k);
            out[t] = base[t] * base_scale + ((s0 + s1) + (s2 + s3)) * g.scale[t];
        }
    }
}

}  // namespace

std::size_t BounceSunGather::entries() const {
    std::size_t n = 0;
    for (const std::vector<Entry>& r : rows) n += r.size();
    return n;
}

void BounceSunGather::set_entries(int col, int row, const std::vector<std::uint32_t>& texel,
                                  const std::vector<float>& weight) {
    const std::size_t t = std::size_t(row) * std::size_t(width) + std::size_t(col);
    std::vector<Entry>& out = rows[std::size_t(row)];
    float top = 0;
    for (float x : weight) top = std::max(top, x);
    scale[t] = top / 65535.0f;
    if (top <= 0) return;
    for (std::size_t k = 0; k < texel.size(); ++k) {
        const long long dc = (long long)(texel[k] % std::uint32_t(width)) - col;
        const long long dr = (long long)(texel[k] / std::uint32_t(width)) - row;
        if (std::max(std::llabs(dc), std::llabs(dr)) > kBounceSunGatherReach)
            throw std::logic_error("BounceSunGather: an entry beyond the gather's reach");
        out.push_back({std::int8_t(dc), std::int8_t(dr), std::uint16_t(std::lround(weight[k] / top * 65535.0f))});
    }
}

void BounceSunGather::apply(const float* sun, float sun_z, float* out, std::vector<float>& scratch,
                            int threads) const {
    const std::size_t n = texels();
    if (n == 0 || width <= 0) return;
    const int row_count = int(n / std::size_t(width));
    const long long work = (long long)(entries() / std::size_t(row_count) + std::size_t(width));
    const float flat_sun = std::max(0.0f, sun_z);
    float* first = bounces >= 2 ? (scratch.resize(n), scratch.data()) : out;
    parallel_rows(row_count, threads, work,
                  [&](int r0, int r1) { gather_rows(*this, sun, far.data(), flat_sun, first, r0, r1); });
    if (bounces < 2) return;
    // b1 + sum_j w_tj b1_j
    parallel_rows(row_count, threads, work, [&](int r0, int r1) { gather_rows(*this, first, first, 1.0f, out, r0, r1); });
}

}  // namespace ts::render
