#include "core/solar/insolation_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/util/angles.hpp"
#include "core/util/error.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/progress_bar.hpp"
#include "core/visibility/fast_atan.hpp"

namespace ts::solar {

std::vector<float> texel_latitudes(const geo::Georef& georef, int threads) {
    const int w = georef.width(), h = georef.height();
    constexpr int kStep = 8;
    const int gw = (w + kStep - 1) / kStep + 1, gh = (h + kStep - 1) / kStep + 1;
    std::vector<double> knots(std::size_t(gw) * gh);
    for (int gy = 0; gy < gh; ++gy)
        for (int gx = 0; gx < gw; ++gx) {
            const glm::dvec2 ll = georef.pixel_to_lonlat(gx * kStep + 0.5, gy * kStep + 0.5);
            if (!std::isfinite(ll.y)) throw InputError("insolation: the DEM's CRS gives no latitude for its texels");
            knots[std::size_t(gy) * gw + gx] = ll.y;
        }
    std::vector<float> lat(std::size_t(w) * h);
    parallel_rows(h, threads, w, [&](int r0, int r1) {
        for (int r = r0; r < r1; ++r) {
            const int gy = r / kStep;
            const double fy = double(r - gy * kStep) / kStep;
            for (int c = 0; c < w; ++c) {
                const int gx = c / kStep;
                const double fx = double(c - gx * kStep) / kStep;
                const double* k0 = &knots[std::size_t(gy) * gw + gx];
                const double* k1 = k0 + gw;
                lat[std::size_t(r) * w + c] = float((1 - fy) * ((1 - fx) * k0[0] + fx * k0[1]) +
                                                    fy * ((1 - fx) * k1[0] + fx * k1[1]));
            }
        }
    });
    return lat;
}

InsolationMap map_rows(const InsolationMap& map, int row0, int rows) {
    if (row0 < 0 || rows < 0 || row0 + rows > map.height) throw std::out_of_range("map_rows: rows outside the map");
    InsolationMap out;
    out.width = map.width, out.height = rows, out.periods = map.periods;
    const std::size_t plane = std::size_t(map.width) * std::size_t(map.height);
    const std::size_t first = std::size_t(row0) * std::size_t(map.width), count = std::size_t(rows) * std::size_t(map.width);
    out.values.resize(std::size_t(map.periods) * kQuantities * count);
    for (std::size_t b = 0; b < std::size_t(map.periods) * kQuantities; ++b)
        std::copy_n(map.values.begin() + std::ptrdiff_t(b * plane + first), count,
                    out.values.begin() + std::ptrdiff_t(b * count));
    if (!map.svf.empty()) out.svf.assign(map.svf.begin() + std::ptrdiff_t(first), map.svf.begin() + std::ptrdiff_t(first + count));
    return out;
}

void bin_horizons(const visibility::HorizonSet& horizons, std::size_t texel, int bins, float* out) {
    const int d_count = horizons.directions;
    const std::size_t plane = horizons.texels();
    for (int j = 0; j < bins; ++j) {
        const double x = double(j) * d_count / bins;
        const int d = int(x);
        const double f = x - d;
        const float a = horizons.angle[std::size_t(d) * plane + texel];
        const float b = horizons.angle[std::size_t((d + 1) % d_count) * plane + texel];
        out[j] = float(a + f * (b - a));
    }
}

InsolationMap integrate_insolation(const InsolationModel& model, const terrain::HeightGrid& grid,
                                   const visibility::HorizonSet& horizons, const render::NormalField& normals,
                                   std::span<const float> latitude_deg, ProgressBar* progress) {
    const std::size_t texels = std::size_t(grid.width) * grid.height;
    if (horizons.texels() != texels || normals.z.size() != texels || latitude_deg.size() != texels)
        throw InputError("insolation: horizons, normals and latitudes must cover the grid");
    InsolationMap map;
    map.width = grid.width;
    map.height = grid.height;
    map.periods = model.periods();
    const std::size_t values_per_texel = std::size_t(map.periods) * kQuantities;
    map.values.assign(values_per_texel * texels, std::numeric_limits<float>::quiet_NaN());
    map.svf.assign(texels, std::numeric_limits<float>::quiet_NaN());
    const int bins = model.settings().azimuth_bins;
    const int directions = horizons.directions;
    const std::size_t plane = horizons.texels();
    parallel_rows(grid.height, model.settings().threads, (long long)grid.width * bins * map.periods,
                  [&](int r0, int r1) {
                      std::vector<InsolationModel::TexelInfo> info;
                      std::vector<std::size_t> index;
                      std::vector<float> svf, out;
                      for (int r = r0; r < r1; ++r) {
                          info.clear();
                          index.clear();
                          for (int c = 0; c < grid.width; ++c) {
                              const std::size_t t = std::size_t(r) * grid.width + c;
                              if (std::isnan(horizons.angle[t]) || std::isnan(grid.z[t])) continue;
                              InsolationModel::TexelInfo ti{glm::vec3(normals.x[t], normals.y[t], normals.z[t]),
                                                            model.band_of(latitude_deg[t]), grid.z[t], 0.0f};
                              if (model.settings().interpolate_bands) {
                                  const auto [b, w] = model.band_between(latitude_deg[t]);
                                  ti.band = b, ti.next_band_weight = w;
                              }
                              info.push_back(ti);
                              index.push_back(t);
                          }
                          const int n = int(index.size());
                          if (n > 0) {
                              // The tilted sky view over the D horizon azimuths (their horizons are exact).
                              svf.assign(std::size_t(n), 0.0f);
                              for (int d = 0; d < directions; ++d) {
                                  const float* hp = horizons.angle.data() + std::size_t(d) * plane;
                                  const double phi = 2 * kPi * d / directions;
                                  const float cp = float(std::cos(phi)), sp = float(std::sin(phi));
                                  for (int i = 0; i < n; ++i) {
                                      const glm::vec3& nn = info[std::size_t(i)].normal;
                                      const float nz = std::max(nn.z, 1e-6f);
                                      const float a = nn.x * cp + nn.y * sp;
                                      const float h = std::max(hp[index[std::size_t(i)]], float(visibility::fast_atan(-a / nz)));
                                      const float sh = std::sin(h), ch = std::cos(h);
                                      svf[std::size_t(i)] += sky_above(h, 2 * sh * ch, ch * ch, a, nz);
                                  }
                              }
                              for (float& v : svf) v = std::clamp(v * 2.0f / float(directions), 0.0f, 1.0f);
                              out.resize(std::size_t(n) * values_per_texel);
                              model.run(n, info.data(),
                                        [&](int j, float* h) {
                                            const double x = double(j) * directions / bins;
                                            const int d = int(x);
                                            const float f = float(x - d);
                                            const float* a = horizons.angle.data() + std::size_t(d) * plane;
                                            const float* b = horizons.angle.data() + std::size_t((d + 1) % directions) * plane;
                                            for (int i = 0; i < n; ++i) {
                                                const std::size_t t = index[std::size_t(i)];
                                                h[i] = a[t] + f * (b[t] - a[t]);
                                            }
                                        },
                                        svf.data(), out.data());
                              for (int i = 0; i < n; ++i) map.svf[index[std::size_t(i)]] = svf[std::size_t(i)];
                              for (int i = 0; i < n; ++i)
                                  for (std::size_t v = 0; v < values_per_texel; ++v)
                                      map.values[v * texels + index[std::size_t(i)]] = out[std::size_t(i) * values_per_texel + v];
                          }
                          if (progress) progress->advance(std::uint64_t(grid.width));
                      }
                  });
    return map;
}

}  // namespace ts::solar
