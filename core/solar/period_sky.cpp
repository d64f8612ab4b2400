#include "core/solar/period_sky.hpp"

#include <algorithm>
#include <cmath>

#include <glm/vec3.hpp>

#include "core/solar/cie_clear_sky.hpp"
#include "core/util/angles.hpp"
#include "core/util/error.hpp"
#include "core/util/parallel_for.hpp"

namespace ts::solar {
namespace {

// Sub-samples per cell and sector: the integrand is smooth at this scale (the circumsolar peak's
// width is ~20 degrees), 2 x 2 midpoints err below 1e-3 of a cell's value.
constexpr int kSub = 2;

}  // namespace

SkyKernel::SkyKernel(SkyGrid grid, int threads) : grid_(grid) {
    if (grid_.sectors < 4 || grid_.cells < 2 || !(grid_.step_rad > 0))
        throw InputError("insolation: the sky grid needs >= 4 sectors and >= 2 cells");
    const int sectors = grid_.sectors, cells = grid_.cells;
    values_.assign(std::size_t(kSunElevations) * std::size_t(sectors) * std::size_t(cells) * 3, 0.0f);
    const double dphi = 2 * kPi / sectors, de = grid_.step_rad;
    parallel_for(kSunElevations, thread_count(threads), [&](int eb, int) {
        const double se = radians(double(eb));
        std::vector<double> v(std::size_t(sectors) * std::size_t(cells) * 3, 0.0);
        double horizontal = 0;
        for (int o = 0; o < sectors; ++o) {
            // In the sector's frame (its centre at phi = 0) the sun is o sectors behind.
            const double sun_phi = -dphi * o;
            const glm::dvec3 sun(std::cos(se) * std::cos(sun_phi), std::cos(se) * std::sin(sun_phi), std::sin(se));
            for (int k = 0; k < cells; ++k)
                for (int a = 0; a < kSub; ++a)
                    for (int b = 0; b < kSub; ++b) {
                        const double phi = dphi * ((a + 0.5) / kSub - 0.5);
                        const double e = grid_.first_rad + de * (k + (b + 0.5) / kSub);
                        const glm::dvec3 w(std::cos(e) * std::cos(phi), std::cos(e) * std::sin(phi), std::sin(e));
                        const double weight = cie_clear_sky_radiance(sun, w) * std::cos(e) * (dphi / kSub) * (de / kSub);
                        double* c = &v[(std::size_t(o) * std::size_t(cells) + std::size_t(k)) * 3];
                        c[0] += weight * w.x, c[1] += weight * w.y, c[2] += weight * w.z;
                        if (e > 0) horizontal += weight * w.z;
                    }
        }
        float* out = values_.data() + std::size_t(eb) * v.size();
        for (std::size_t i = 0; i < v.size(); ++i) out[i] = float(v[i] / horizontal);
    });
}

PeriodSky::PeriodSky(const SkyGrid& grid)
    : grid_(grid),
      sun_weight_(std::size_t(SkyKernel::kSunElevations) * std::size_t(grid.sectors), 0.0),
      row_(std::size_t(grid.cells + 1) * 4),
      cells_(grid.cells),
      first_(float(grid.first_rad)),
      inv_step_(float(1.0 / grid.step_rad)) {}

void PeriodSky::add_sun(double elevation_rad, double phi_rad, double horizontal_wh) {
    if (!(elevation_rad > 0) || !(horizontal_wh > 0)) return;
    horizontal_wh_ += horizontal_wh;
    const double x = std::min(degrees(elevation_rad), double(SkyKernel::kSunElevations - 1));
    const int e0 = std::min(int(x), SkyKernel::kSunElevations - 2);
    const double fe = x - e0;
    const int sectors = grid_.sectors;
    double y = std::fmod(phi_rad / (2 * kPi) * sectors, double(sectors));
    if (y < 0) y += sectors;
    const int s0 = int(y) % sectors, s1 = (s0 + 1) % sectors;
    const double fs = y - std::floor(y);
    auto at = [&](int e, int s) -> double& { return sun_weight_[std::size_t(e) * std::size_t(sectors) + std::size_t(s)]; };
    at(e0, s0) += horizontal_wh * (1 - fe) * (1 - fs);
    at(e0, s1) += horizontal_wh * (1 - fe) * fs;
    at(e0 + 1, s0) += horizontal_wh * fe * (1 - fs);
    at(e0 + 1, s1) += horizontal_wh * fe * fs;
}

void PeriodSky::finish(const SkyKernel& kernel) {
    const int sectors = grid_.sectors, cells = grid_.cells;
    if (kernel.grid().sectors != sectors || kernel.grid().cells != cells)
        throw std::logic_error("PeriodSky: kernel of another grid");
    // In each sector's own frame, then turned to ENU once.
    std::vector<double> local(std::size_t(sectors) * std::size_t(cells) * 3, 0.0);
    for (int eb = 0; eb < SkyKernel::kSunElevations; ++eb)
        for (int u = 0; u < sectors; ++u) {
            const double weight = sun_weight_[std::size_t(eb) * std::size_t(sectors) + std::size_t(u)];
            if (weight == 0) continue;
            for (int s = 0; s < sectors; ++s) {
                const float* k = kernel.cells(eb, (s - u + sectors) % sectors);
                double* l = &local[std::size_t(s) * std::size_t(cells) * 3];
                for (int i = 0; i < cells * 3; ++i) l[i] += weight * double(k[i]);
            }
        }
    cumulative_.assign(std::size_t(sectors) * row_, 0.0f);
    for (int s = 0; s < sectors; ++s) {
        const double phi = 2 * kPi * s / sectors, c = std::cos(phi), sn = std::sin(phi);
        double sum[3] = {0, 0, 0};
        float* out = cumulative_.data() + std::size_t(s) * row_;
        for (int k = cells - 1; k >= 0; --k) {
            const double* l = &local[(std::size_t(s) * std::size_t(cells) + std::size_t(k)) * 3];
            sum[0] += l[0] * c - l[1] * sn;
            sum[1] += l[0] * sn + l[1] * c;
            sum[2] += l[2];
            for (int i = 0; i < 3; ++i) out[std::size_t(k) * 4 + std::size_t(i)] = float(sum[i]);
        }
    }
    sun_weight_ = {};
}

}  // namespace ts::solar
