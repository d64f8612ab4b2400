#include "core/render/bounce_sun_gather.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "core/util/parallel_for.hpp"

#if defined(__GNUC__) && defined(__x86_64__)
#include <immintrin.h>
#define TS_BOUNCE_SUN_AVX2 1
#endif

namespace ts::render {
namespace {

constexpr int kChunkLanes = BounceSunGather::kLanes;
// GCC/Clang vector extension: half a chunk's lanes, one SSE register on the baseline build.
using Float4 = float __attribute__((vector_size(16)));
using Int4 = std::int32_t __attribute__((vector_size(16)));
using Byte4 = std::uint8_t __attribute__((vector_size(4)));
[[gnu::always_inline]] inline void load4(Float4& v, const float* p) {
    std::memcpy(&v, p, sizeof v);
}
// The writer's table: (dc, dr) within the reach as one index.
constexpr int kKeySide = 2 * kBounceSunGatherReach + 1;

// One chunk: out[l] = base_scale base[l] + scale[l] sum_k weight[k][l] here[offset[k] + l], for
// the chunk's `lanes` receivers. `here` and `base` point at its first receiver; `here` is read
// for all kChunkLanes lanes at every offset (apply()'s margins), `base` only for the receivers.
inline void chunk_portable(const std::int32_t* offset, const std::uint8_t* weight, std::uint32_t count,
                           const float* here, const float* base, float base_scale, const float* scale, float* out,
                           int lanes) {
    float sum[kChunkLanes] = {};
    for (std::uint32_t k = 0; k < count; ++k) {
        const float* v = here + offset[k];
        const std::uint8_t* w = weight + std::size_t(k) * kChunkLanes;
        for (int l = 0; l < kChunkLanes; ++l) sum[l] += float(w[l]) * v[l];
    }
    for (int l = 0; l < lanes; ++l) out[l] = base[l] * base_scale + sum[l] * scale[l];
}

#ifdef TS_BOUNCE_SUN_AVX2
bool bounce_sun_has_avx2() {
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

// chunk_portable with the 8 lanes in one register: two sums, each offset's values one unaligned
// load. On Grenoble the bounce's per-frame CPU time is 3 ms where per-receiver entries took 8
// (docs/rendering.md, "How the weights are kept").
[[gnu::target("avx2,fma")]] void chunk_avx2(const std::int32_t* offset, const std::uint8_t* weight, std::uint32_t count,
                                            const float* here, const float* base, float base_scale, const float* scale,
                                            float* out, int lanes) {
    __m256 s0 = _mm256_setzero_ps(), s1 = _mm256_setzero_ps();
#define TS_BOUNCE_TERM(K, SUM)                                                                            \
    SUM = _mm256_fmadd_ps(_mm256_cvtepi32_ps(_mm256_cvtepu8_epi32(_mm_loadl_epi64(                        \
                              reinterpret_cast<const __m128i*>(weight + std::size_t(K) * kChunkLanes)))), \
                          _mm256_loadu_ps(here + offset[K]), SUM)
    std::uint32_t k = 0;
    for (; k + 2 <= count; k += 2) {
        TS_BOUNCE_TERM(k, s0);
        TS_BOUNCE_TERM(k + 1, s1);
    }
    if (k < count) TS_BOUNCE_TERM(k, s0);
#undef TS_BOUNCE_TERM
    const __m256 sum = _mm256_add_ps(s0, s1);
    if (lanes == kChunkLanes) {
        _mm256_storeu_ps(out, _mm256_fmadd_ps(_mm256_loadu_ps(base), _mm256_set1_ps(base_scale),
                                              _mm256_mul_ps(sum, _mm256_loadu_ps(scale))));
        return;
    }
    alignas(32) float part[kChunkLanes];
    _mm256_store_ps(part, sum);
    for (int l = 0; l < lanes; ++l) out[l] = base[l] * base_scale + part[l] * scale[l];
}
#endif

// n values between zero margins. A frame overwrites all n: the margins are zeroed once per layout.
float* with_margins(std::vector<float>& buffer, std::size_t n, std::size_t margin) {
    if (buffer.size() != n + 2 * margin) buffer.assign(n + 2 * margin, 0.0f);
    return buffer.data() + margin;
}

}  // namespace

BounceSunGather::BounceSunGather(int bounces, int width, int height)
    : bounces_(bounces),
      width_(width),
      rows_(std::size_t(height)),
      scale_(std::size_t(width) * std::size_t(height), 0.0f),
      far_(std::size_t(width) * std::size_t(height), 0.0f) {
    const std::size_t chunks = (std::size_t(width) + kChunkLanes - 1) / kChunkLanes;
    for (Row& r : rows_) r.chunk_begin.assign(chunks + 1, 0);
}

std::size_t BounceSunGather::slots() const {
    std::size_t n = 0;
    for (const Row& r : rows_) n += r.offset.size();
    return n;
}

std::size_t BounceSunGather::entries() const {
    std::size_t n = 0;
    for (const Row& r : rows_)
        for (std::uint8_t w : r.weight) n += w != 0;
    return n;
}

BounceSunGather::Writer::Writer(BounceSunGather& g)
    : g_(g), slot_of_(std::size_t(kKeySide) * kKeySide), stamp_(std::size_t(kKeySide) * kKeySide, 0) {}

void BounceSunGather::Writer::add_far(int col, int row, float far) {
    g_.far_[std::size_t(row) * std::size_t(g_.width_) + std::size_t(col)] = far;
}

void BounceSunGather::Writer::start(int row, int chunk) {
    if (row != row_) {
        finish();
        row_ = row;
        begin_.assign(g_.rows_[std::size_t(row)].chunk_begin.size(), 0);
    }
    if (chunk != chunk_) flush(), chunk_ = chunk;
}

namespace {
int sun_table_key(int dc, int dr) {
    if (std::max(std::abs(dc), std::abs(dr)) > kBounceSunGatherReach)
        throw std::logic_error("BounceSunGather: an entry beyond the gather's reach");
    return (dr + kBounceSunGatherReach) * kKeySide + dc + kBounceSunGatherReach;
}
}  // namespace

void BounceSunGather::Writer::add(int col, int row, const std::vector<std::uint32_t>& texel,
                                  const std::vector<float>& weight, float far) {
    add_far(col, row, far);
    start(row, col / kChunkLanes);
    const std::uint32_t w = std::uint32_t(g_.width_);
    const int lane = col % kChunkLanes;
    for (std::size_t k = 0; k < texel.size(); ++k) {
        key_[lane].push_back(sun_table_key(int(texel[k] % w) - col, int(texel[k] / w) - row));
        weight_[lane].push_back(weight[k]);
    }
}

void BounceSunGather::Writer::add_chunk(int col0, int row, unsigned lanes, const ChunkEntry* entries, std::size_t count,
                                        const float* far) {
    for (int l = 0; l < kChunkLanes; ++l)
        if (lanes >> l & 1u) add_far(col0 + l, row, far[l]);
    start(row, col0 / kChunkLanes);
    ++epoch_;
    keys_.clear();
    sums_.clear();
    for (std::size_t e = 0; e < count; ++e) {
        const std::size_t key = std::size_t(sun_table_key(entries[e].dc, entries[e].dr));
        if (stamp_[key] != epoch_) {
            stamp_[key] = epoch_, slot_of_[key] = std::uint32_t(keys_.size());
            keys_.push_back(int(key));
            sums_.resize(sums_.size() + kChunkLanes, 0.0f);
        }
        float* sum = sums_.data() + std::size_t(slot_of_[key]) * kChunkLanes;
        for (int l = 0; l < kChunkLanes; ++l) sum[l] += entries[e].weight[l];
    }
    store_chunk();
}

// The chunk's offsets are the union of its receivers' (in the order first seen); each receiver's
// weights are summed per offset, then stored in 8 bits against its largest.
void BounceSunGather::Writer::flush() {
    if (chunk_ < 0) return;
    ++epoch_;
    keys_.clear();
    sums_.clear();
    for (int l = 0; l < kChunkLanes; ++l)
        for (std::size_t k = 0; k < key_[l].size(); ++k) {
            const std::size_t key = std::size_t(key_[l][k]);
            if (stamp_[key] != epoch_) {
                stamp_[key] = epoch_, slot_of_[key] = std::uint32_t(keys_.size());
                keys_.push_back(key_[l][k]);
                sums_.resize(sums_.size() + kChunkLanes, 0.0f);
            }
            sums_[std::size_t(slot_of_[key]) * kChunkLanes + std::size_t(l)] += weight_[l][k];
        }
    store_chunk();
}

void BounceSunGather::Writer::store_chunk() {
    const std::size_t first = offset_.size();
    for (int key : keys_) {
        const long long dr = key / kKeySide - kBounceSunGatherReach, dc = key % kKeySide - kBounceSunGatherReach;
        const long long o = dr * g_.width_ + dc;
        offset_.push_back(std::int32_t(o));
        reach_ = std::max(reach_, std::llabs(o));
    }
    weight8_.resize(offset_.size() * kChunkLanes, 0);
    // The 8 receivers' codes as vectors, 4 lanes at a time (their carries are independent).
    Float4 top[2] = {}, carry[2] = {};
    for (std::size_t k = 0; k < keys_.size(); ++k)
        for (int h = 0; h < 2; ++h) {
            Float4 s;
            load4(s, sums_.data() + k * kChunkLanes + 4 * h);
            top[h] = s > top[h] ? s : top[h];
        }
    for (int l = 0; l < kChunkLanes; ++l) {
        const int col = chunk_ * kChunkLanes + l;
        if (col < g_.width_)  // 0 where a receiver has no weights, as it was
            g_.scale_[std::size_t(row_) * std::size_t(g_.width_) + std::size_t(col)] = top[l / 4][l % 4] / 255.0f;
        key_[l].clear();
        weight_[l].clear();
    }
    // 8 bits against the receiver's largest, each code's rounding carried into the next (the
    // sum of the codes stays within half a code of the weights'). The march's weights can come
    // out below 0 by rounding (1e-16..1e-14 on level ground): 0. x >= -0.5, so truncating
    // x + 0.5 rounds it (ties up). A receiver without weight gets codes 0.
    const Float4 zero{};
    for (int h = 0; h < 2; ++h) {
        const Float4 to_code = top[h] > zero ? 255.0f / top[h] : zero;
        for (std::size_t k = 0; k < keys_.size(); ++k) {
            Float4 s;
            load4(s, sums_.data() + k * kChunkLanes + 4 * h);
            const Float4 x = (s > zero ? s * to_code : zero) + carry[h];
            Float4 c = __builtin_convertvector(__builtin_convertvector(x + 0.5f, Int4), Float4);
            c = c > 255.0f ? zero + 255.0f : c;
            carry[h] = x - c;
            const Byte4 code = __builtin_convertvector(__builtin_convertvector(c, Int4), Byte4);
            std::memcpy(weight8_.data() + (first + k) * kChunkLanes + 4 * h, &code, sizeof code);
        }
    }
    // Chunks without receivers in between keep no offsets: their begins follow the last one's end.
    for (std::size_t c = std::size_t(chunk_) + 1; c < begin_.size(); ++c) begin_[c] = std::uint32_t(offset_.size());
    chunk_ = -1;
}

// The row's weights into the gather, at their size: a row grows in the writer's buffers.
void BounceSunGather::Writer::finish() {
    flush();
    if (row_ < 0) return;
    Row& row = g_.rows_[std::size_t(row_)];
    row.offset.assign(offset_.begin(), offset_.end());
    row.weight.assign(weight8_.begin(), weight8_.end());
    row.chunk_begin = begin_;
    row.reach = reach_;
    offset_.clear();
    weight8_.clear();
    reach_ = 0;
    row_ = -1;
}

void BounceSunGather::gather_rows(const float* values, const float* base, float base_scale, float* out, int r0, int r1,
                                  bool vector_units) const {
    const std::size_t w = std::size_t(width_);
#ifdef TS_BOUNCE_SUN_AVX2
    const bool avx2 = vector_units && bounce_sun_has_avx2();
#else
    (void)vector_units;
#endif
    for (int r = r0; r < r1; ++r) {
        const Row& row = rows_[std::size_t(r)];
        for (std::size_t c = 0, chunk = 0; c < w; c += kChunkLanes, ++chunk) {
            const std::size_t t = std::size_t(r) * w + c;
            const std::uint32_t k0 = row.chunk_begin[chunk], count = row.chunk_begin[chunk + 1] - k0;
            const int lanes = int(std::min<std::size_t>(kChunkLanes, w - c));
            const std::int32_t* offset = row.offset.data() + k0;
            const std::uint8_t* weight = row.weight.data() + std::size_t(k0) * kChunkLanes;
#ifdef TS_BOUNCE_SUN_AVX2
            if (avx2) {
                chunk_avx2(offset, weight, count, values + t, base + t, base_scale, scale_.data() + t, out + t, lanes);
                continue;
            }
#endif
            chunk_portable(offset, weight, count, values + t, base + t, base_scale, scale_.data() + t, out + t, lanes);
        }
    }
}

float* BounceSunGather::sun_values(Scratch& scratch) const {
    long long reach = 0;
    for (const Row& r : rows_) reach = std::max(reach, r.reach);
    // A chunk's lanes read its offsets from every receiver, and up to kChunkLanes past a row's last.
    const std::size_t n = texels(), margin = std::size_t(reach) + kChunkLanes;
    if (scratch.texels != n || scratch.margin != margin) {
        scratch.values.clear(), scratch.first.clear();
        scratch.texels = n, scratch.margin = margin;
    }
    return with_margins(scratch.values, n, margin);
}

void BounceSunGather::apply(const float* sun, float sun_z, float* out, Scratch& scratch, int threads,
                            bool vector_units) const {
    float* values = sun_values(scratch);
    parallel_rows(int(rows_.size()), threads, width_ * 2LL, [&](int r0, int r1) {
        for (std::size_t t = std::size_t(r0) * std::size_t(width_), e = std::size_t(r1) * std::size_t(width_); t < e;
             ++t)
            values[t] = sun[t] == sun[t] ? sun[t] : 0.0f;
    });
    apply(sun_z, out, scratch, threads, vector_units);
}

void BounceSunGather::apply(float sun_z, float* out, Scratch& scratch, int threads, bool vector_units) const {
    const std::size_t n = texels();
    if (n == 0 || width_ <= 0) return;
    if (scratch.texels != n) throw std::logic_error("BounceSunGather::apply: the values were not written for it");
    const float* values = scratch.values.data() + scratch.margin;
    const int row_count = int(rows_.size());
    const long long work = (long long)(slots() / std::size_t(row_count)) * kChunkLanes + width_;
    const float flat_sun = std::max(0.0f, sun_z);
    float* first = bounces_ >= 2 ? with_margins(scratch.first, n, scratch.margin) : out;
    parallel_rows(row_count, threads, work,
                  [&](int r0, int r1) { gather_rows(values, far_.data(), flat_sun, first, r0, r1, vector_units); });
    if (bounces_ < 2) return;
    // b1 + sum_j w_tj b1_j
    parallel_rows(row_count, threads, work,
                  [&](int r0, int r1) { gather_rows(first, first, 1.0f, out, r0, r1, vector_units); });
}

}  // namespace ts::render

#undef TS_BOUNCE_SUN_AVX2
