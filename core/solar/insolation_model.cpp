#include "core/solar/insolation_model.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/solar/esra_clear_sky.hpp"
#include "core/solar/period_sky.hpp"
#include "core/util/angles.hpp"
#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/progress_bar.hpp"
#include "core/visibility/fast_atan.hpp"

namespace ts::solar {
namespace {

// The summed sky is smooth at this azimuth resolution (the circumsolar brightening spans ~20
// degrees); more sectors cost memory and lookups, not accuracy.
constexpr int kMaxSkySectors = 64;

std::vector<double> even_steps(double lo, double hi, double step) {
    if (!(hi - lo > 1e-9) || !(step > 0)) return {lo};
    const int n = int(std::ceil((hi - lo) / step - 1e-9)) + 1;
    std::vector<double> v(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) v[std::size_t(i)] = lo + (hi - lo) * i / (n - 1);
    return v;
}

}  // namespace

void check_settings(const InsolationSettings& s) {
    for (double tl : s.linke_monthly)
        if (!(tl >= 0) || tl > 10) throw InputError("Linke turbidity " + std::to_string(tl) + ": must be in (0, 10]");
    if (!(s.albedo >= 0 && s.albedo <= 1)) throw QuantityError(ts::Quantity::ground_albedo, std::to_string(s.albedo), "must be in [0, 1]");
    if (!(s.clear_sky_index > 0 && s.clear_sky_index <= 2))
        throw QuantityError(ts::Quantity::clear_sky_index, std::to_string(s.clear_sky_index), "must be in (0, 2]");
    if (!(s.step_minutes > 0) || s.step_minutes > 60)
        throw QuantityError(ts::Quantity::time_step, std::to_string(s.step_minutes), "minutes, must be in (0, 60]");
    if (s.azimuth_bins < 4 || s.azimuth_bins > 4096) throw InputError("insolation: azimuth bins must be in [4, 4096]");
    if (s.svf_stride < 1 || s.azimuth_bins % s.svf_stride != 0)
        throw InputError("insolation: the sky view's stride must divide the azimuth bins");
    if (!(s.sky_band_step_deg > 0)) throw InputError("insolation: the sky's latitude step must be > 0");
    if (s.periods.empty()) throw InputError("insolation: no period to sum over");
    for (const auto& p : s.periods)
        if (!(p.end > p.begin)) throw InputError("insolation: empty period " + p.label);
}

const char* quantity_name(int q) {
    static const char* names[] = {"global", "beam", "diffuse", "reflected", "sun_hours"};
    return names[q];
}

const char* quantity_unit(int q) {
    return q == kSunHours ? "h" : "kWh/m2";
}

InsolationModel::InsolationModel(const InsolationSettings& settings, double lat_min_deg, double lat_max_deg,
                                 double band_step_deg, double z_min_m, double z_max_m, double level_step_m,
                                 ProgressBar* progress)
    : settings_(settings) {
    check_settings(settings_);
    band_lat_ = even_steps(std::clamp(lat_min_deg, -90.0, 90.0), std::clamp(lat_max_deg, -90.0, 90.0), band_step_deg);
    band_first_ = band_lat_.front();
    band_step_ = band_lat_.size() > 1 ? band_lat_[1] - band_lat_[0] : 1.0;
    level_z_ = even_steps(z_min_m, z_max_m, level_step_m);
    const int bins = settings_.azimuth_bins;
    cos_phi_.resize(std::size_t(bins));
    sin_phi_.resize(std::size_t(bins));
    for (int j = 0; j < bins; ++j) {
        cos_phi_[std::size_t(j)] = std::cos(2 * kPi * j / bins);
        sin_phi_[std::size_t(j)] = std::sin(2 * kPi * j / bins);
    }
    const std::vector<EphemerisSample> path =
        sample_sun_path(settings_.periods, settings_.step_minutes, settings_.clock_longitude_deg);
    samples_ = path.size();
    const std::size_t n_periods = settings_.periods.size(), n_levels = level_z_.size();
    tables_.assign(n_periods * band_lat_.size() * n_levels, AzimuthTable(bins, settings_.horizon_grid));
    // The sky: sectors on the horizon azimuths; one sky band per sky_band_step of latitude,
    // summed at the latitude band nearest it.
    sky_stride_ = settings_.svf_stride;
    while (bins / sky_stride_ > kMaxSkySectors && bins % (2 * sky_stride_) == 0) sky_stride_ *= 2;
    SkyGrid sky_grid;
    sky_grid.sectors = bins / sky_stride_;
    const int per_sky_band = std::max(1, int(std::lround(settings_.sky_band_step_deg / band_step_)));
    const int n_bands = int(band_lat_.size());
    sky_bands_ = (n_bands - 1) / per_sky_band + 1;
    sky_band_of_.resize(std::size_t(n_bands));
    for (int b = 0; b < n_bands; ++b) sky_band_of_[std::size_t(b)] = std::min(sky_bands_ - 1, int(std::lround(double(b) / per_sky_band)));
    const SkyKernel kernel(sky_grid, settings_.threads);
    skies_.assign(n_periods * std::size_t(sky_bands_), PeriodSky(sky_grid));
    const double r = settings_.sun_radius_rad;
    const double lon = settings_.clock_longitude_deg;
    parallel_for(int(band_lat_.size()), thread_count(settings_.threads), [&](int b, int) {
        // The sun's geometry at this latitude once, then each level's energies.
        struct Up {
            LocalSun sun;
            std::size_t sample;
            int bin;
        };
        std::vector<Up> up;
        up.reserve(path.size() / 2 + 16);
        for (std::size_t i = 0; i < path.size(); ++i) {
            const LocalSun sun = local_sun(path[i], band_lat_[std::size_t(b)], lon, settings_.refraction, settings_.grid_north_deg);
            if (!(sun.elevation_rad > 0)) continue;
            const int bin = int(std::lround(sun.phi_rad * bins / (2 * kPi))) % bins;
            up.push_back({sun, i, bin});
        }
        // This band sums the sky of its sky band when it is that band's own latitude.
        const int sky_band = sky_band_of_[std::size_t(b)];
        const bool sums_sky = std::min(n_bands - 1, sky_band * per_sky_band) == b;
        std::vector<std::vector<AzimuthTable::Sample>> per_bin(static_cast<std::size_t>(bins));
        for (std::size_t l = 0; l < n_levels; ++l) {
            std::size_t u = 0;
            for (std::size_t p = 0; p < n_periods; ++p) {
                AzimuthTable& table = tables_[(p * band_lat_.size() + std::size_t(b)) * n_levels + l];
                for (auto& v : per_bin) v.clear();
                for (; u < up.size() && path[up[u].sample].period == int(p); ++u) {
                    const EphemerisSample& s = path[up[u].sample];
                    const LocalSun& sun = up[u].sun;
                    const double g0 = extraterrestrial_normal_irradiance(s.day_of_year);
                    const double tl = settings_.linke_monthly[std::size_t(s.month0)];
                    const double beam = beam_normal_irradiance(g0, tl, sun.altitude_rad, level_z_[l]);
                    const double diffuse = diffuse_horizontal_irradiance(g0, tl, sun.altitude_rad);
                    const double dt = s.hours;
                    AzimuthTable::Sample sample{sun.elevation_rad, {}};
                    for (int c = 0; c < 3; ++c) sample.w[std::size_t(c)] = beam * dt * sun.direction[c];
                    sample.w[3] = dt;
                    per_bin[std::size_t(up[u].bin)].push_back(sample);
                    table.open_global_wh += (beam * sun.direction.z + diffuse) * dt;
                    // The sky does not depend on the height (ESRA's diffuse has no elevation term).
                    if (sums_sky && l == 0)
                        skies_[p * std::size_t(sky_bands_) + std::size_t(sky_band)].add_sun(sun.elevation_rad, sun.phi_rad,
                                                                                            diffuse * dt);
                }
                for (int j = 0; j < bins; ++j) table.finish_bin(j, per_bin[std::size_t(j)], r);
                if (sums_sky && l == 0) skies_[p * std::size_t(sky_bands_) + std::size_t(sky_band)].finish(kernel);
            }
        }
        if (progress) progress->advance(1);
    });
}

int InsolationModel::band_of(double latitude_deg) const {
    const long b = std::lround((latitude_deg - band_first_) / band_step_);
    return int(std::clamp<long>(b, 0, long(band_lat_.size()) - 1));
}

std::pair<int, float> InsolationModel::band_between(double latitude_deg) const {
    const int last = int(band_lat_.size()) - 1;
    if (last == 0) return {0, 0.0f};
    const double x = std::clamp((latitude_deg - band_first_) / band_step_, 0.0, double(last));
    const int b = std::min(int(x), last - 1);
    return {b, float(x - b)};
}

std::size_t InsolationModel::table_bytes() const {
    std::size_t n = 0;
    for (const auto& t : tables_) n += t.bytes();
    for (const auto& s : skies_) n += s.bytes();
    return n;
}

double tilted_sky_view_factor(const float* bin_horizon, int bins, const glm::dvec3& n, int stride) {
    const double nz = std::max(n.z, 1e-6);
    double sum = 0;
    for (int j = 0; j < bins; j += stride) {
        const double phi = 2 * kPi * j / bins;
        const double a = n.x * std::cos(phi) + n.y * std::sin(phi);
        const double h = std::max(double(bin_horizon[j]), std::atan(-a / nz));
        sum += sky_above(h, std::sin(2 * h), std::cos(h) * std::cos(h), a, nz);
    }
    return std::clamp(sum * (2 * kPi * stride / bins) / kPi, 0.0, 1.0);
}

void InsolationModel::texel(const float* bin_horizon, const glm::vec3& normal, int band, double z_m, float* out) const {
    const TexelInfo info{normal, band, float(z_m)};
    const float svf = float(tilted_sky_view_factor(bin_horizon, settings_.azimuth_bins, glm::dvec3(normal),
                                                   settings_.svf_stride));
    run(1, &info, [&](int j, float* h) { h[0] = bin_horizon[j]; }, &svf, out);
}

void InsolationModel::run(int n, const TexelInfo* info, const std::function<void(int, float*)>& horizons_of_bin,
                          const float* svf, float* out) const {
    const int bins = settings_.azimuth_bins;
    const int periods = int(settings_.periods.size());
    // Per texel: its two elevation levels and the weight of the upper one.
    std::vector<int> l0(static_cast<std::size_t>(n), 0);
    std::vector<float> w1(static_cast<std::size_t>(n), 0.0f), inv_nz(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        if (level_z_.size() > 1) {
            const double x = std::clamp((double(info[i].z) - level_z_.front()) / (level_z_[1] - level_z_[0]), 0.0,
                                        double(level_z_.size() - 1));
            l0[std::size_t(i)] = std::min(int(x), int(level_z_.size()) - 2);
            w1[std::size_t(i)] = float(x - l0[std::size_t(i)]);
        }
        inv_nz[std::size_t(i)] = 1.0f / std::max(info[i].normal.z, 1e-6f);
    }
    std::vector<float> acc(std::size_t(n) * std::size_t(periods) * kTableStride, 0.0f);
    std::vector<float> sky_acc(std::size_t(n) * std::size_t(periods) * 4, 0.0f);  // per texel and period: ENU sum
    std::vector<float> h(static_cast<std::size_t>(n));
    // Bin by bin over all the texels, so one bin's tables stay in cache across them.
    for (int j = 0; j < bins; ++j) {
        horizons_of_bin(j, h.data());
        const float cj = float(cos_phi_[std::size_t(j)]), sj = float(sin_phi_[std::size_t(j)]);
        for (int i = 0; i < n; ++i) {
            const TexelInfo& t = info[i];
            const float a = t.normal.x * cj + t.normal.y * sj;
            // The receiver's own plane hides what is behind it, whatever the grid's horizon says.
            const float hz = std::max(h[std::size_t(i)], float(visibility::fast_atan(-a * inv_nz[std::size_t(i)])));
            const int lo = l0[std::size_t(i)];
            const float wb = w1[std::size_t(i)];
            float* ai = acc.data() + std::size_t(i) * std::size_t(periods) * kTableStride;
            const float bw = t.next_band_weight;
            if (j % sky_stride_ == 0) {
                float* si = sky_acc.data() + std::size_t(i) * std::size_t(periods) * 4;
                for (int p = 0; p < periods; ++p) sky(p, t.band).add_visible(j / sky_stride_, hz, 1.0f, si + std::size_t(p) * 4);
            }
            for (int p = 0; p < periods; ++p) {
                float* ap = ai + std::size_t(p) * kTableStride;
                table(p, t.band, lo).add_visible(j, hz, (1.0f - wb) * (1.0f - bw), ap);
                if (wb > 0) table(p, t.band, lo + 1).add_visible(j, hz, wb * (1.0f - bw), ap);
                if (bw > 0) {
                    table(p, t.band + 1, lo).add_visible(j, hz, (1.0f - wb) * bw, ap);
                    if (wb > 0) table(p, t.band + 1, lo + 1).add_visible(j, hz, wb * bw, ap);
                }
            }
        }
    }
    const double k = settings_.clear_sky_index / 1000.0;  // Wh -> kWh
    for (int i = 0; i < n; ++i) {
        const glm::dvec3 nn(info[i].normal);
        const int lo = l0[std::size_t(i)], hi = std::min(lo + 1, int(level_z_.size()) - 1);
        const double wb = w1[std::size_t(i)], wa = 1 - wb;
        for (int p = 0; p < periods; ++p) {
            const float* ap = acc.data() + (std::size_t(i) * std::size_t(periods) + std::size_t(p)) * kTableStride;
            const float* sp = sky_acc.data() + (std::size_t(i) * std::size_t(periods) + std::size_t(p)) * 4;
            double open = 0;
            const double bw = info[i].next_band_weight;
            for (int b = 0; b < (bw > 0 ? 2 : 1); ++b) {
                const double wband = b == 0 ? 1 - bw : bw;
                const AzimuthTable& t0 = table(p, info[i].band + b, lo);
                const AzimuthTable& t1 = table(p, info[i].band + b, hi);
                open += wband * (wa * t0.open_global_wh + wb * t1.open_global_wh);
            }
            const double beam = std::max(0.0, nn.x * ap[0] + nn.y * ap[1] + nn.z * ap[2]) * k;
            const double diffuse = std::max(0.0, nn.x * sp[0] + nn.y * sp[1] + nn.z * sp[2]) * k;
            const double reflected = settings_.albedo * open * (1 - svf[i]) * k;
            float* o = out + (std::size_t(i) * std::size_t(periods) + std::size_t(p)) * kQuantities;
            o[kGlobal] = float(beam + diffuse + reflected);
            o[kBeam] = float(beam);
            o[kDiffuse] = float(diffuse);
            o[kReflected] = float(reflected);
            o[kSunHours] = float(ap[3]);
        }
    }
}

}  // namespace ts::solar
