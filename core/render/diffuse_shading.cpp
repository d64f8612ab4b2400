#include "core/render/diffuse_shading.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <variant>
#include <vector>

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#include <immintrin.h>
#endif

#include "core/render/bounce_transfer.hpp"
#include "core/util/parallel_for.hpp"

namespace ts::render {
namespace {

// GCC/Clang vector extension, as in transfer.cpp: 8 lanes (one AVX register on the clone built
// for it, two SSE registers otherwise).
using Float8 = float __attribute__((vector_size(32)));

#if defined(__FLT16_MAX__) && defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define TS_DIFFUSE_HALF 1
// fp16 storage; values are converted with the compiler's _Float16 (round to nearest even).
using Half = _Float16;
#endif

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
// AVX2 + FMA clone of the fp32 kernels, picked at load time.
#define TS_DIFFUSE_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define TS_DIFFUSE_CLONES
#endif

constexpr int kLanes = 8;
constexpr float kPiF = 3.14159265358979f;

// Normals of the compact (fp16) layout: signed 16-bit fixed point, n * 32767. In [-1, 1] that
// is within 1.5e-5 per component (fp16 would be 2.4e-4 near 1, which is where the sun term's
// precision matters: n . s under a grazing sun).
using NormalQ = std::int16_t;
constexpr float kNormalScale = 32767.0f;
using Short8 = std::int16_t __attribute__((vector_size(16)));

// One record per 8 texels: everything the loop reads for them except the sun visibility.
// (16-byte alignment keeps every layout's size a multiple of 16 without padding: half K = 9 is
// 240 bytes; the loads are unaligned anyway.)
template <class S, int K>
struct alignas(16) Block {
    using Normal = std::conditional_t<std::is_same_v<S, float>, float, NormalQ>;
    static constexpr bool kBounce = false;
    S t[K][kLanes];
    S albedo[3][kLanes];
    Normal normal[3][kLanes];
};
// With bounced light: the bounce transfer's bands 0..1 too (its sun part, per frame).
template <class S, int K>
struct alignas(16) BounceBlock : Block<S, K> {
    static constexpr bool kBounce = true;
    S b[kBounceSunCoefficients][kLanes];
};

// How 8 stored values become 8 floats (through a reference: returning a 32-byte vector by
// value has a different ABI with and without AVX, which GCC warns about).
struct LoadSingle {
    [[gnu::always_inline]] static void load(Float8& v, const float (&a)[kLanes]) { std::memcpy(&v, a, sizeof v); }
    [[gnu::always_inline]] static void load(Float8& v, const NormalQ (&a)[kLanes]) {
        Short8 q;
        std::memcpy(&q, a, sizeof q);
        v = __builtin_convertvector(q, Float8) * (1.0f / kNormalScale);
    }
};
#ifdef TS_DIFFUSE_HALF
// Portable: one conversion per value (GCC 12 does not vectorise _Float16 -> float without
// AVX512-FP16, so this is the slow fallback for CPUs without F16C).
struct LoadHalfScalar {
    [[gnu::always_inline]] static void load(Float8& v, const Half (&a)[kLanes]) {
        for (int k = 0; k < kLanes; ++k) v[k] = float(a[k]);
    }
};
// F16C: 8 values in one vcvtph2ps.
struct LoadHalfF16c {
    [[gnu::target("avx2,fma,f16c")]] static void load(Float8& v, const Half (&a)[kLanes]) {
        v = _mm256_cvtph_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(a)));
    }
};
#endif

// The frame's light, one scalar per coefficient and channel, and the sun.
struct FrameConstants {
    float r[16], g[16], b[16];
    float s[3], e[3];
    float y[16], e_sun[3];  // the sun's direction in SH, Y_i(s), and E_sun (the bounce's sun part)
    const glm::vec3* sky_add = nullptr;  // per texel, added to <T, L> before its clamp (or none)
};

template <class Load, class BlockT>
[[gnu::always_inline]] inline void shade_blocks(const BlockT* blocks, std::size_t b0, std::size_t b1,
                                                std::size_t texels, const float* vis, const FrameConstants& c,
                                                glm::vec3* out) {
    const Float8 zero{};
    for (std::size_t b = b0; b < b1; ++b) {
        constexpr int K = sizeof(blocks->t) / sizeof(blocks->t[0]);
        const BlockT& blk = blocks[b];
        Float8 r = zero, g = zero, bl = zero;
        Float8 x, y, z;
        for (int i = 0; i < K; ++i) {
            Load::load(x, blk.t[i]);
            r += x * c.r[i];
            g += x * c.g[i];
            bl += x * c.b[i];
        }
        const std::size_t t = b * kLanes;
        const std::size_t n = std::min<std::size_t>(kLanes, texels - t);
        if (c.sky_add)
            for (std::size_t k = 0; k < n; ++k) {
                const glm::vec3 a = c.sky_add[t + k];
                r[k] += a.x, g[k] += a.y, bl[k] += a.z;
            }
        // Irradiance is never negative; a sky concentrated in a few degrees (the twilight glow
        // just after sunset) rings below 0 in 16 coefficients on slopes facing away from it.
        // Written so that a void's NaN stays NaN.
        r = r < zero ? zero : r;
        g = g < zero ? zero : g;
        bl = bl < zero ? zero : bl;
        if constexpr (BlockT::kBounce) {
            Float8 u = zero;
            for (int i = 0; i < kBounceSunCoefficients; ++i) {
                Load::load(x, blk.b[i]);
                u += x * c.y[i];
            }
            r += u * c.e_sun[0];
            g += u * c.e_sun[1];
            bl += u * c.e_sun[2];
        }
        LoadSingle::load(x, blk.normal[0]);
        LoadSingle::load(y, blk.normal[1]);
        LoadSingle::load(z, blk.normal[2]);
        Float8 cos_s = x * c.s[0] + y * c.s[1] + z * c.s[2];
        cos_s = cos_s > zero ? cos_s : zero;
        Float8 v = zero;
        if (n == kLanes) std::memcpy(&v, vis + t, sizeof v);
        else
            for (std::size_t k = 0; k < n; ++k) v[k] = vis[t + k];
        v = v == v ? v : zero;  // NaN (void) -> no sun
        const Float8 w = v * cos_s;
        Load::load(x, blk.albedo[0]);
        Load::load(y, blk.albedo[1]);
        Load::load(z, blk.albedo[2]);
        const Float8 o_r = x * (r + w * c.e[0]);
        const Float8 o_g = y * (g + w * c.e[1]);
        const Float8 o_b = z * (bl + w * c.e[2]);
        for (std::size_t k = 0; k < n; ++k) out[t + k] = glm::vec3(o_r[k], o_g[k], o_b[k]);
    }
}

// One function per layout and instruction set (target_clones and C++ overloads or templates
// do not mix well in GCC 12, hence the names).
#define TS_SINGLE_KERNEL(NAME, BLOCK)                                                                          \
    TS_DIFFUSE_CLONES void NAME(const BLOCK* p, std::size_t b0, std::size_t b1, std::size_t n, const float* vis, \
                                const FrameConstants& c, glm::vec3* out) {                                   \
        shade_blocks<LoadSingle>(p, b0, b1, n, vis, c, out);                                                 \
    }                                                                                                        \
    void kernel(const BLOCK* p, std::size_t b0, std::size_t b1, std::size_t n, const float* vis,              \
                const FrameConstants& c, glm::vec3* out) {                                                   \
        NAME(p, b0, b1, n, vis, c, out);                                                                     \
    }
using Single9 = Block<float, 9>;
using Single16 = Block<float, 16>;
using Single9B = BounceBlock<float, 9>;
using Single16B = BounceBlock<float, 16>;
TS_SINGLE_KERNEL(shade_single9, Single9)
TS_SINGLE_KERNEL(shade_single16, Single16)
TS_SINGLE_KERNEL(shade_single9b, Single9B)
TS_SINGLE_KERNEL(shade_single16b, Single16B)
#ifdef TS_DIFFUSE_HALF
bool has_f16c() {
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("f16c");
}
#define TS_HALF_KERNEL(NAME, BLOCK)                                                                            \
    [[gnu::target("avx2,fma,f16c")]] void NAME##_f16c(const BLOCK* p, std::size_t b0, std::size_t b1,           \
                                                      std::size_t n, const float* vis, const FrameConstants& c,  \
                                                      glm::vec3* out) {                                        \
        shade_blocks<LoadHalfF16c>(p, b0, b1, n, vis, c, out);                                               \
    }                                                                                                        \
    void NAME##_scalar(const BLOCK* p, std::size_t b0, std::size_t b1, std::size_t n, const float* vis,         \
                       const FrameConstants& c, glm::vec3* out) {                                            \
        shade_blocks<LoadHalfScalar>(p, b0, b1, n, vis, c, out);                                             \
    }                                                                                                        \
    void kernel(const BLOCK* p, std::size_t b0, std::size_t b1, std::size_t n, const float* vis,              \
                const FrameConstants& c, glm::vec3* out) {                                                   \
        (has_f16c() ? NAME##_f16c : NAME##_scalar)(p, b0, b1, n, vis, c, out);                                 \
    }
using Half9 = Block<Half, 9>;
using Half16 = Block<Half, 16>;
using Half9B = BounceBlock<Half, 9>;
using Half16B = BounceBlock<Half, 16>;
TS_HALF_KERNEL(shade_half9, Half9)
TS_HALF_KERNEL(shade_half16, Half16)
TS_HALF_KERNEL(shade_half9b, Half9B)
TS_HALF_KERNEL(shade_half16b, Half16B)
#endif

// 8 values into a block's lanes: floats as they are; fp16 through F16C where the CPU has it
// (one instruction for 8, the same rounding to nearest even: libgcc's conversion one at a time
// took ~5% of `render`'s CPU time, more with the bounce, whose values take its slow path).
void to_lanes(float (&dst)[kLanes], const float* src, bool) { std::memcpy(dst, src, sizeof dst); }
#ifdef TS_DIFFUSE_HALF
[[gnu::target("avx2,fma,f16c")]] void halves_f16c(Half (&dst)[kLanes], const float* src) {
    _mm_storeu_si128(reinterpret_cast<__m128i*>(dst),
                     _mm256_cvtps_ph(_mm256_loadu_ps(src), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC));
}
void to_lanes(Half (&dst)[kLanes], const float* src, bool f16c) {
    if (f16c) return halves_f16c(dst, src);
    for (int l = 0; l < kLanes; ++l) dst[l] = Half(src[l]);
}
#endif

template <class BlockT>
std::vector<BlockT> pack(const DiffuseShading::Inputs& in) {
    constexpr int K = sizeof(BlockT::t) / sizeof(BlockT::t[0]);
    const std::size_t n = in.texels;
#ifdef TS_DIFFUSE_HALF
    const bool f16c = has_f16c();
#else
    const bool f16c = false;
#endif
    std::vector<BlockT> blocks((n + kLanes - 1) / kLanes);
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        BlockT& blk = blocks[b];
        const std::size_t t0 = b * kLanes, m = std::min<std::size_t>(kLanes, n - t0);
        float lane[kLanes] = {};  // padding lanes are 0
        for (int i = 0; i < K; ++i) {
            std::memcpy(lane, in.transfer + std::size_t(i) * n + t0, m * sizeof(float));
            to_lanes(blk.t[i], lane, f16c);
        }
        if constexpr (BlockT::kBounce)
            for (int i = 0; i < kBounceSunCoefficients; ++i) {
                for (std::size_t l = 0; l < m; ++l) {
                    const float v = in.bounce[std::size_t(i) * n + t0 + l];
                    lane[l] = v == v ? v : 0.0f;
                }
                to_lanes(blk.b[i], lane, f16c);
            }
        for (int c = 0; c < 3; ++c) {
            std::memcpy(lane, in.albedo[c] + t0, m * sizeof(float));
            to_lanes(blk.albedo[c], lane, f16c);
            for (std::size_t l = 0; l < m; ++l) {
                const float v = in.normal[c][t0 + l];
                if constexpr (std::is_same_v<typename BlockT::Normal, float>) blk.normal[c][l] = v;
                else blk.normal[c][l] = NormalQ(std::lround(std::clamp(v, -1.0f, 1.0f) * kNormalScale));
            }
        }
    }
    return blocks;
}

}  // namespace

struct DiffuseShading::Storage {
    std::size_t texels = 0;
    std::variant<
#ifdef TS_DIFFUSE_HALF
        std::vector<Block<Half, 9>>, std::vector<Block<Half, 16>>, std::vector<BounceBlock<Half, 9>>,
        std::vector<BounceBlock<Half, 16>>,
#endif
        std::vector<Block<float, 9>>, std::vector<Block<float, 16>>, std::vector<BounceBlock<float, 9>>,
        std::vector<BounceBlock<float, 16>>>
        blocks;
};

DiffuseShading::DiffuseShading(const Inputs& in) : storage_(std::make_unique<Storage>()) {
    if (in.coefficients != 9 && in.coefficients != 16)
        throw std::invalid_argument("DiffuseShading: 9 or 16 coefficients");
    if (in.texels > 0 && (!in.transfer || !in.normal[0] || !in.normal[1] || !in.normal[2] || !in.albedo[0] ||
                          !in.albedo[1] || !in.albedo[2]))
        throw std::invalid_argument("DiffuseShading: null input array");
    storage_->texels = in.texels;
    const bool nine = in.coefficients == 9, bounce = in.bounce != nullptr;
#ifdef TS_DIFFUSE_HALF
    if (in.precision == Precision::half) {
        if (bounce) {
            if (nine) storage_->blocks = pack<BounceBlock<Half, 9>>(in);
            else storage_->blocks = pack<BounceBlock<Half, 16>>(in);
        } else {
            if (nine) storage_->blocks = pack<Block<Half, 9>>(in);
            else storage_->blocks = pack<Block<Half, 16>>(in);
        }
        return;
    }
#endif
    // Without a compiler fp16 type, Precision::half falls back to fp32 (same results, more bytes).
    if (bounce) {
        if (nine) storage_->blocks = pack<BounceBlock<float, 9>>(in);
        else storage_->blocks = pack<BounceBlock<float, 16>>(in);
    } else {
        if (nine) storage_->blocks = pack<Block<float, 9>>(in);
        else storage_->blocks = pack<Block<float, 16>>(in);
    }
}

DiffuseShading::~DiffuseShading() = default;

void DiffuseShading::update_rect(int grid_width, int col0, int row0, int w, int h, const float* transfer) {
    if (w <= 0 || h <= 0) return;
    if (!transfer) throw std::invalid_argument("DiffuseShading::update_rect: null transfer");
    if (col0 < 0 || row0 < 0 || col0 + w > grid_width ||
        std::size_t(row0 + h) * std::size_t(grid_width) > storage_->texels)
        throw std::invalid_argument("DiffuseShading::update_rect: rectangle outside the texels");
    const std::size_t n = std::size_t(w) * std::size_t(h);
    std::visit(
        [&](auto& blocks) {
            using BlockT = typename std::decay_t<decltype(blocks)>::value_type;
            using S = std::decay_t<decltype(blocks[0].t[0][0])>;
            constexpr int K = sizeof(BlockT::t) / sizeof(BlockT::t[0]);
            for (int r = 0; r < h; ++r)
                for (int c = 0; c < w; ++c) {
                    const std::size_t t = std::size_t(row0 + r) * std::size_t(grid_width) + std::size_t(col0 + c);
                    const std::size_t k = std::size_t(r) * std::size_t(w) + std::size_t(c);
                    BlockT& blk = blocks[t / kLanes];
                    for (int i = 0; i < K; ++i) blk.t[i][t % kLanes] = S(transfer[std::size_t(i) * n + k]);
                }
        },
        storage_->blocks);
}

std::size_t DiffuseShading::texels() const { return storage_->texels; }

std::size_t DiffuseShading::bytes() const {
    return std::visit([](const auto& v) { return v.size() * sizeof(v[0]); }, storage_->blocks);
}

void DiffuseShading::shade(const std::array<glm::vec3, 16>& light_sh, const float* sun_vis,
                           const glm::vec3& sun_dir, const glm::vec3& e_diffuse, glm::vec3* out, int threads) const {
    shade(light_sh, sun_vis, sun_dir, e_diffuse, std::array<float, 16>{}, out, threads);
}

void DiffuseShading::shade(const std::array<glm::vec3, 16>& light_sh, const float* sun_vis,
                           const glm::vec3& sun_dir, const glm::vec3& e_diffuse, const std::array<float, 16>& sun_sh,
                           glm::vec3* out, int threads) const {
    shade(light_sh, sun_vis, sun_dir, e_diffuse, sun_sh, nullptr, out, threads);
}

void DiffuseShading::shade(const std::array<glm::vec3, 16>& light_sh, const float* sun_vis,
                           const glm::vec3& sun_dir, const glm::vec3& e_diffuse, const std::array<float, 16>& sun_sh,
                           const glm::vec3* sky_add, glm::vec3* out, int threads) const {
    const std::size_t texels = storage_->texels;
    if (texels == 0) return;
    if (!sun_vis || !out) throw std::invalid_argument("DiffuseShading::shade: null input or output array");
    FrameConstants c;
    for (int i = 0; i < 16; ++i) {
        c.r[i] = light_sh[std::size_t(i)].r;
        c.g[i] = light_sh[std::size_t(i)].g;
        c.b[i] = light_sh[std::size_t(i)].b;
    }
    for (int k = 0; k < 3; ++k) c.s[k] = sun_dir[k], c.e[k] = e_diffuse[k], c.e_sun[k] = e_diffuse[k] * kPiF;
    for (int i = 0; i < 16; ++i) c.y[i] = sun_sh[std::size_t(i)];
    c.sky_add = sky_add;
    std::visit(
        [&](const auto& blocks) {
            const std::size_t count = blocks.size();
            // Rows of 64 blocks (512 texels) for parallel_rows' equal bands.
            constexpr std::size_t kRow = 64;
            const int rows = int((count + kRow - 1) / kRow);
            parallel_rows(rows, threads, static_cast<long long>(kRow * kLanes * 16), [&](int r0, int r1) {
                kernel(blocks.data(), std::size_t(r0) * kRow, std::min(count, std::size_t(r1) * kRow), texels,
                       sun_vis, c, out);
            });
        },
        storage_->blocks);
}

}  // namespace ts::render
