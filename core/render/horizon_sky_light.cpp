#include "core/render/horizon_sky_light.hpp"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/util/angles.hpp"
#include "core/util/parallel_for.hpp"
#include "core/visibility/fast_atan.hpp"

namespace ts::render {
namespace {

// Azimuth samples per sector of the per-frame table: the sky varies smoothly in azimuth outside
// the sun's disc (not in it), so a few per sector do: twice as many changed the Cycles crop's
// error by under 0.01% with the aureole in the sky.
int azimuth_samples(int sectors) { return std::max(4, 96 / sectors); }

// The per-frame look-up table: the coarse table's cumulative integrals interpolated to this many
// nodes, read at the nearest one (0.35 degrees apart: under 0.1% of a sector's light), so that a
// texel's sector reads 9 contiguous floats and no interpolation weights.
constexpr int kFineNodes = 512;
constexpr std::uint16_t kVoid = 0xffff;

}  // namespace

light::SkyOptions sky_for(light::SkyOptions sky, const SkyLightSettings& settings) {
    if (settings.mode == SkyLightSettings::Mode::horizons && !sky.aureole_given) sky.aureole_deg = 0.0;
    return sky;
}

int effective_sectors(const SkyLightSettings& settings, int directions) {
    int s = std::clamp(settings.sectors, 1, std::max(1, directions));
    while (directions % s != 0) --s;
    return s;
}

HorizonSkyLight::HorizonSkyLight(const visibility::HorizonSet& horizons, const NormalField& normals,
                                 const SkyLightSettings& settings, int threads)
    : texels_(horizons.texels()), sectors_(effective_sectors(settings, horizons.directions)),
      directions_(horizons.directions), steps_(settings.elevation_steps), normals_(normals) {
    const int d_count = horizons.directions;
    if (d_count < 1) throw std::invalid_argument("HorizonSkyLight: no horizon azimuths");
    if (steps_ < 2) throw std::invalid_argument("HorizonSkyLight: 2 or more elevation steps");
    if (normals.x.size() != texels_ || normals.y.size() != texels_ || normals.z.size() != texels_)
        throw std::invalid_argument("HorizonSkyLight: normals and horizons differ in size");
    node_.assign(std::size_t(sectors_) * texels_, 0);
    const int per = d_count / sectors_;
    const int width = horizons.width;
    std::vector<float> cos_phi(static_cast<std::size_t>(d_count)), sin_phi(static_cast<std::size_t>(d_count));
    for (int d = 0; d < d_count; ++d) {
        cos_phi[std::size_t(d)] = float(std::cos(visibility::azimuth_rad(d, d_count)));
        sin_phi[std::size_t(d)] = float(std::sin(visibility::azimuth_rad(d, d_count)));
    }
    const float half_pi = float(kPi / 2);
    parallel_rows(horizons.height, threads, (long long)width * d_count, [&](int r0, int r1) {
        // A row at a time, each loop straight-line over its texels so that it vectorises.
        std::vector<float> sum(static_cast<std::size_t>(width)), nz(static_cast<std::size_t>(width));
        for (int r = r0; r < r1; ++r) {
            const std::size_t t0 = std::size_t(r) * std::size_t(width);
            const float* nx = normals.x.data() + t0;
            const float* ny = normals.y.data() + t0;
            for (int c = 0; c < width; ++c) nz[std::size_t(c)] = std::max(normals.z[t0 + std::size_t(c)], 1e-6f);
            for (int s = 0; s < sectors_; ++s) {
                std::fill(sum.begin(), sum.end(), 0.0f);
                for (int j = 0; j < per; ++j) {
                    const int d = s * per + j;
                    const float cp = cos_phi[std::size_t(d)], sp = sin_phi[std::size_t(d)];
                    const float* h = horizons.plane(d) + t0;
                    for (int c = 0; c < width; ++c) {
                        // The texel's own plane at this azimuth: a cos e + n_z sin e = 0.
                        const float a = nx[c] * cp + ny[c] * sp;
                        const float plane = visibility::fast_atan_lanes(-a / nz[std::size_t(c)]);
                        const float hc = std::min(std::max(h[c], -half_pi), half_pi);  // NaN (void) stays NaN
                        sum[std::size_t(c)] += h[c] > plane ? hc : (h[c] == h[c] ? plane : h[c]);
                    }
                }
                // Texel-major: a texel's S nodes are one read.
                std::uint16_t* out = node_.data() + t0 * std::size_t(sectors_) + std::size_t(s);
                for (int c = 0; c < width; ++c) {
                    const double e0 = double(sum[std::size_t(c)]) / per;
                    out[std::size_t(c) * std::size_t(sectors_)] =
                        e0 == e0 ? std::uint16_t(std::lround(std::clamp((e0 + kPi / 2) / kPi, 0.0, 1.0) * kFineNodes))
                                 : kVoid;
                }
            }
        }
    });
}

std::vector<glm::vec3> HorizonSkyLight::table(const light::Sky& sky) const {
    const int m_count = steps_ + 1;
    std::vector<glm::vec3> tab(std::size_t(sectors_) * m_count * 3, glm::vec3(0.0f));
    const double width = 2 * kPi / sectors_;
    const double de = kPi / steps_;
    // A sky with fine detail (a map's sun in its pixels) is sampled twice per detail, in
    // azimuth and in sub-steps of elevation, so that no pixel falls between samples.
    const double detail = sky.lighting_detail_rad();
    const int qa = detail > 0 ? std::max(azimuth_samples(sectors_), int(std::ceil(2 * width / detail)))
                              : azimuth_samples(sectors_);
    const int sub = detail > 0 ? std::max(1, int(std::ceil(2 * de / detail))) : 1;
    // Two-point Gauss-Legendre per elevation (sub-)step.
    const double g = 0.5 / std::sqrt(3.0);
    // Sector s starts where its first horizon azimuth's share begins: the exact transfer's
    // trapezoid rule gives azimuth d the span phi_d +- pi / D.
    const double phi0 = -kPi / directions_;
    std::vector<double> cos_a(static_cast<std::size_t>(qa)), sin_a(static_cast<std::size_t>(qa));
    for (int s = 0; s < sectors_; ++s) {
        for (int a = 0; a < qa; ++a) {
            const double phi = phi0 + s * width + (a + 0.5) * width / qa;
            cos_a[std::size_t(a)] = std::cos(phi), sin_a[std::size_t(a)] = std::sin(phi);
        }
        glm::dvec3 acc[3] = {};
        glm::vec3* col = tab.data() + std::size_t(s) * m_count * 3;
        // Filled from the zenith down: node m_count - 1 is +90 degrees (nothing above it).
        for (int m = steps_ - 1; m >= 0; --m) {
            const double ds = de / sub;
            for (int k = 0; k < sub; ++k)
                for (int q = 0; q < 2; ++q) {
                    const double e = -kPi / 2 + m * de + k * ds + ds * (0.5 + (q == 0 ? -g : g));
                    const double ce = std::cos(e), se = std::sin(e);
                    for (int a = 0; a < qa; ++a) {
                        const glm::dvec3 w(ce * cos_a[std::size_t(a)], ce * sin_a[std::size_t(a)], se);
                        const glm::dvec3 l = glm::dvec3(sky.lighting_radiance(w)) * (ce * 0.5 * ds * width / qa / kPi);
                        acc[0] += l * w.x;
                        acc[1] += l * w.y;
                        acc[2] += l * w.z;
                    }
                }
            for (int k = 0; k < 3; ++k) col[std::size_t(m) * 3 + k] = glm::vec3(acc[k]);
        }
    }
    return tab;
}

void HorizonSkyLight::irradiance_over_pi(const light::Sky& sky, glm::vec3* out, int threads) const {
    const std::vector<glm::vec3> tab = table(sky);
    const int m_count = steps_ + 1;
    // fine[s][node][k * 3 + c]
    std::vector<float> fine(std::size_t(sectors_) * (kFineNodes + 1) * 9);
    for (int s = 0; s < sectors_; ++s)
        for (int m = 0; m <= kFineNodes; ++m) {
            const double p = double(m) * steps_ / kFineNodes;
            const int i = std::min(int(p), steps_ - 1);
            const float f = float(p - i);
            for (int k = 0; k < 3; ++k) {
                const glm::vec3 a = tab[(std::size_t(s) * m_count + i) * 3 + k];
                const glm::vec3 b = tab[(std::size_t(s) * m_count + i + 1) * 3 + k];
                const glm::vec3 v = a + f * (b - a);
                for (int c = 0; c < 3; ++c) fine[(std::size_t(s) * (kFineNodes + 1) + m) * 9 + k * 3 + c] = v[c];
            }
        }
    const float nan = std::numeric_limits<float>::quiet_NaN();
    parallel_rows(int((texels_ + 511) / 512), threads, 512LL * sectors_ * 12, [&](int r0, int r1) {
        const std::size_t end = std::min(texels_, std::size_t(r1) * 512);
        for (std::size_t t = std::size_t(r0) * 512; t < end; ++t) {
            const float nx = normals_.x[t], ny = normals_.y[t], nz = normals_.z[t];
            float e[3] = {0, 0, 0};
            bool void_texel = false;
            for (int s = 0; s < sectors_; ++s) {
                const std::uint16_t i = node_[t * std::size_t(sectors_) + std::size_t(s)];
                void_texel |= i == kVoid;
                const float* c = fine.data() + (std::size_t(s) * (kFineNodes + 1) + (i == kVoid ? 0 : i)) * 9;
                e[0] += nx * c[0] + ny * c[3] + nz * c[6];
                e[1] += nx * c[1] + ny * c[4] + nz * c[7];
                e[2] += nx * c[2] + ny * c[5] + nz * c[8];
            }
            out[t] = void_texel ? glm::vec3(nan) : glm::vec3(e[0], e[1], e[2]);
        }
    });
}

}  // namespace ts::render
