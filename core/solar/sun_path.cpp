#include "core/solar/sun_path.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "core/light/sun_position.hpp"
#include "core/util/angles.hpp"
#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"

namespace ts::solar {
namespace {

using std::chrono::microseconds;

constexpr double kKnotMinutes = 20.0;

// The geocentric sun every 20 minutes over [begin, end], hour angle unwrapped.
struct Knots {
    light::UtcTime begin;
    std::vector<double> declination, hour_angle;  // radians
};

Knots make_knots(light::UtcTime begin, light::UtcTime end) {
    Knots k;
    k.begin = begin - microseconds(std::int64_t(kKnotMinutes * 60e6));
    const double span_min = std::chrono::duration<double, std::ratio<60>>(end - k.begin).count();
    const int n = int(std::ceil(span_min / kKnotMinutes)) + 2;
    k.declination.resize(std::size_t(n));
    k.hour_angle.resize(std::size_t(n));
    double previous = 0;
    for (int i = 0; i < n; ++i) {
        light::SunPositionInput in;
        in.time = k.begin + microseconds(std::int64_t(i * kKnotMinutes * 60e6));
        in.atmosphere.pressure_hpa = 0;  // no refraction: only the geocentric values are kept
        const light::SunPosition p = light::sun_position(in);
        double h = radians(p.observer_hour_angle_deg);
        if (i > 0) h += 2 * kPi * std::round((previous - h) / (2 * kPi));
        k.declination[std::size_t(i)] = radians(p.declination_deg);
        k.hour_angle[std::size_t(i)] = previous = h;
    }
    return k;
}

}  // namespace

std::vector<EphemerisSample> sample_sun_path(const std::vector<InsolationPeriod>& periods, double step_minutes,
                                             double clock_longitude_deg) {
    if (!(step_minutes > 0) || step_minutes > 60)
        throw QuantityError(ts::Quantity::time_step, "", std::to_string(step_minutes) + " minutes (must be in (0, 60])");
    if (periods.empty()) throw InputError("insolation: no period to sum over");
    light::UtcTime first = periods.front().begin, last = periods.front().end;
    for (const auto& p : periods) {
        if (!(p.end > p.begin)) throw InputError("insolation: empty period " + p.label);
        first = std::min(first, p.begin), last = std::max(last, p.end);
    }
    const Knots knots = make_knots(first, last);
    std::vector<EphemerisSample> samples;
    for (std::size_t pi = 0; pi < periods.size(); ++pi) {
        const auto& p = periods[pi];
        const double minutes = std::chrono::duration<double, std::ratio<60>>(p.end - p.begin).count();
        const long n = long(std::ceil(minutes / step_minutes - 1e-9));
        const double step = minutes / double(n);
        samples.reserve(samples.size() + std::size_t(n));
        for (long i = 0; i < n; ++i) {
            const double t_min = (double(i) + 0.5) * step;
            const light::UtcTime t = p.begin + microseconds(std::int64_t(std::llround(t_min * 60e6)));
            const double x = std::chrono::duration<double, std::ratio<60>>(t - knots.begin).count() / kKnotMinutes;
            const auto k = std::size_t(x);
            const double f = x - double(k);
            EphemerisSample s;
            s.declination_rad = knots.declination[k] + f * (knots.declination[k + 1] - knots.declination[k]);
            s.greenwich_hour_angle_rad = knots.hour_angle[k] + f * (knots.hour_angle[k + 1] - knots.hour_angle[k]);
            s.hours = step / 60.0;
            s.period = int(pi);
            const LocalDay day = local_day(t, clock_longitude_deg);
            s.month0 = day.month0;
            s.day_of_year = day.day_of_year;
            samples.push_back(s);
        }
    }
    return samples;
}

LocalSun local_sun(const EphemerisSample& s, double latitude_deg, double longitude_deg, bool refraction,
                   double grid_north_deg) {
    const double lat = radians(latitude_deg);
    const double h = s.greenwich_hour_angle_rad + radians(longitude_deg);
    const double sd = std::sin(s.declination_rad), cd = std::cos(s.declination_rad);
    const double sl = std::sin(lat), cl = std::cos(lat);
    const double ch = std::cos(h);
    const double east = -cd * std::sin(h);
    const double north = cl * sd - sl * cd * ch;
    const double up = std::clamp(sl * sd + cl * cd * ch, -1.0, 1.0);
    LocalSun sun;
    sun.altitude_rad = std::asin(up);
    sun.elevation_rad = sun.altitude_rad;
    if (refraction) {
        light::Atmosphere standard;
        sun.elevation_rad += radians(light::refraction_correction_deg(degrees(sun.altitude_rad), standard));
    }
    double phi = std::fmod(std::atan2(north, east) - radians(grid_north_deg), 2 * kPi);
    if (phi < 0) phi += 2 * kPi;
    sun.phi_rad = phi;
    const double ce = std::cos(sun.elevation_rad);
    sun.direction = {ce * std::cos(phi), ce * std::sin(phi), std::sin(sun.elevation_rad)};
    return sun;
}

}  // namespace ts::solar
