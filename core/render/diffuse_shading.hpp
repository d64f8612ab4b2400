#pragma once
// FrameRenderer's per-frame diffuse loop (sky transfer + sun + albedo) in one pass over a
// compact copy of its inputs, made once:
//
//   out_t = albedo_t * (<T_t, L> + vis_t * max(0, n_t . s) * E_sun / pi
//                      + <B_t, Y(s)> E_sun)                                  (vis NaN -> 0)
//
// B_t the bounced light's transfer (bounce_transfer.hpp), when there is one: its sun part, over
// bands 0..1 (kBounceSunCoefficients: 8 more bytes per texel in fp16).
// Per block of 8 texels, one contiguous record: the K transfer coefficients that matter
// (K = 9 when the band correction has zeroed band 3, else 16), the albedo and the normal.
// Precision::half: T and albedo fp16, the normal 16-bit fixed point (n . s within 3e-5: the sun
// term under a grazing sun is where a normal's precision shows); Precision::single: all fp32.
// Why: the unfused pass read T as 16 float planes (64 B/texel), wrote the sky term and read it
// back, then read normal, albedo and the sky term (152 B/texel in all with the output); this
// one reads 30 B/texel (half, K = 9) or 60 B/texel (single) plus the sun visibility and writes
// the output (58 or 88 B/texel in all). Memory-bound like the old one: the bytes are the speed.
//
// Accuracy against shade_transfer + the unfused loop (tests/render/diffuse_shading_test.cpp):
// single: float rounding (rel. 1e-5); half: each stored T_i and albedo within 2^-12 relative,
// so the radiance is within 1e-3 of the size of its terms (relative, unless <T, L> is a
// cancellation of larger terms, which the smooth sky SH does not produce).
#include <array>
#include <cstddef>
#include <memory>

#include <glm/vec3.hpp>

namespace ts::render {

class DiffuseShading {
public:
    enum class Precision { half, single };
    struct Inputs {
        std::size_t texels = 0;
        const float* transfer = nullptr;  // [16][texels], as transfer_vectors writes it
        int coefficients = 16;            // 9 (band 3 is zero: only bands 0..2 kept) or 16
        const float* normal[3] = {};      // unit normals, planes x, y, z
        const float* albedo[3] = {};      // linear albedo, planes r, g, b
        const float* bounce = nullptr;    // [>= 4][texels] bounce transfer B (bands 0..1 read), or none (NaN -> 0)
        Precision precision = Precision::half;
    };
    explicit DiffuseShading(const Inputs& in);
    ~DiffuseShading();
    DiffuseShading(const DiffuseShading&) = delete;
    DiffuseShading& operator=(const DiffuseShading&) = delete;

    std::size_t texels() const;
    // Rewrites the transfer of the texels of a rectangle: columns [col0, col0 + w), rows
    // [row0, row0 + h) of a grid `grid_width` texels wide (texel t = row * grid_width + col);
    // `transfer` is [16][w * h], the rectangle's texels row-major. Albedo and normals stay.
    void update_rect(int grid_width, int col0, int row0, int w, int h, const float* transfer);
    // Bytes of the compact copy (what each frame streams besides sun_vis and out).
    std::size_t bytes() const;
    // The formula above for every texel; `sun_vis` has texels() entries, `e_diffuse` is
    // E_sun / pi (0 when the sun is down). NaN transfer gives NaN.
    void shade(const std::array<glm::vec3, 16>& light_sh, const float* sun_vis, const glm::vec3& sun_dir,
               const glm::vec3& e_diffuse, glm::vec3* out, int threads) const;
    // With the bounce's sun part: `sun_sh` is Y_i(s), the SH basis at the sun's direction
    // (ignored without a bounce transfer).
    void shade(const std::array<glm::vec3, 16>& light_sh, const float* sun_vis, const glm::vec3& sun_dir,
               const glm::vec3& e_diffuse, const std::array<float, 16>& sun_sh, glm::vec3* out, int threads) const;
    // With more sky irradiance / pi per texel, `sky_add` [texels] (HorizonSkyLight's), added to
    // <T, L> before the clamp at 0: then T holds what the sky light over the horizons leaves out.
    void shade(const std::array<glm::vec3, 16>& light_sh, const float* sun_vis, const glm::vec3& sun_dir,
               const glm::vec3& e_diffuse, const std::array<float, 16>& sun_sh, const glm::vec3* sky_add,
               glm::vec3* out, int threads) const;

private:
    struct Storage;
    std::unique_ptr<Storage> storage_;
};

}  // namespace ts::render
