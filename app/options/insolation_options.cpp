#include "app/options/insolation_options.hpp"

#include <algorithm>
#include <cstdio>

#include "app/options/within_range.hpp"
#include "core/util/error.hpp"

namespace ts::app {

bool InsolationArgs::any_given() const {
    return std::any_of(added.begin(), added.end(), [](const CLI::Option* o) { return o->count() > 0; });
}

void add_insolation_options(CLI::App& cmd, InsolationArgs& a) {
    a.added = {
        cmd.add_option("--year", a.year, "Sum over this calendar year (local mean solar time at the DEM's centre)"),
        cmd.add_option("--from", a.from, "First day, YYYY-MM-DD (with --to)"),
        cmd.add_option("--to", a.to, "Last day, YYYY-MM-DD, included"),
        cmd.add_option("--linke", a.linke, "Linke turbidity of the whole range (r.sun's linke_value)")
            ->capture_default_str(),
        cmd.add_option("--linke-monthly", a.linke_monthly, "Linke turbidity per month, 12 values January..December")
            ->delimiter(',')
            ->type_name("L1,...,L12"),
        cmd.add_option("--albedo", a.albedo, "Ground albedo for the reflected irradiation, [0, 1]")
            ->capture_default_str(),
        cmd.add_option("--clear-sky-index", a.clear_sky_index,
                       "Real-sky / clear-sky ratio applied to beam and diffuse (1 = clear sky)")
            ->capture_default_str(),
        cmd.add_option("--step", a.step_minutes,
                       "Time step of the sun's path in minutes (costs only in the sun tables)")
            ->capture_default_str(),
        cmd.add_option("--reflection-directions", a.reflection.directions,
                       "Azimuths along which each texel gathers the light reflected by the terrain it sees "
                       "(a divisor of --directions; 0: an isotropic ground lit like open flat land)")
            ->capture_default_str()
            ->check(within(0, 1024)),
        // At most 250: a tile block's halo is 256 texels, and its core texels must see within it.
        cmd.add_option("--reflection-radius", a.reflection.radius_texels,
                       "How far the reflection's gather looks, texels (farther terrain is lit like open flat land)")
            ->capture_default_str()
            ->check(within(1, 250)),
        cmd.add_option("--reflection-growth", a.reflection.growth,
                       "Ratio of each step of the reflection's gather to the last (the first is one texel)")
            ->capture_default_str()
            ->check(within(1.01, 4)),
    };
}

std::pair<solar::CalendarDate, solar::CalendarDate> insolation_dates(const InsolationArgs& a) {
    if (a.year != 0) {
        if (!a.from.empty() || !a.to.empty()) throw InputError("--year: give either --year or --from/--to, not both");
        if (a.year < 1 || a.year > 5999) throw InputError("--year " + std::to_string(a.year) + ": must be in 1..5999");
        return {{a.year, 1, 1}, {a.year, 12, 31}};
    }
    if (a.from.empty() || a.to.empty()) throw InputError("insolation: give --year Y, or --from DATE and --to DATE");
    const solar::CalendarDate first = solar::parse_calendar_date(a.from, "--from");
    const solar::CalendarDate last = solar::parse_calendar_date(a.to, "--to");
    if (first.year > 5999 || last.year > 5999) throw InputError("--from/--to: years must be in 1..5999");
    return {first, last};
}

std::string describe_insolation_sum(const InsolationArgs& a) {
    const auto [first, last] = insolation_dates(a);
    const solar::InsolationSettings s = insolation_settings(a);
    std::string linke;
    for (double tl : s.linke_monthly) linke += (linke.empty() ? "" : ",") + std::to_string(tl);
    char text[256];
    std::snprintf(text, sizeof text, "%04d-%02d-%02d..%04d-%02d-%02d albedo %.9g index %.9g step %.9g linke ",
                  first.year, first.month, first.day, last.year, last.month, last.day, s.albedo, s.clear_sky_index,
                  s.step_minutes);
    // The gather changes the reflected and global values: off, or its directions, radius, growth.
    char gather[96] = " reflection isotropic";
    if (a.reflection.enabled())
        std::snprintf(gather, sizeof gather, " reflection %d %.9g %.9g", a.reflection.directions,
                      a.reflection.radius_texels, a.reflection.growth);
    return text + linke + gather;
}

solar::InsolationSettings insolation_settings(const InsolationArgs& a) {
    solar::InsolationSettings s;
    if (!a.linke_monthly.empty()) {
        if (a.linke_monthly.size() != 12)
            throw InputError("--linke-monthly: needs 12 values (January..December), got " +
                             std::to_string(a.linke_monthly.size()));
        std::copy(a.linke_monthly.begin(), a.linke_monthly.end(), s.linke_monthly.begin());
    } else {
        s.linke_monthly.fill(a.linke);
    }
    for (double tl : s.linke_monthly)
        if (!(tl > 0) || tl > 10) throw InputError("Linke turbidity " + std::to_string(tl) + ": must be in (0, 10]");
    s.albedo = a.albedo;
    s.clear_sky_index = a.clear_sky_index;
    s.step_minutes = a.step_minutes;
    solar::check_reflection_settings(a.reflection);
    return s;
}

}  // namespace ts::app
