#include "core/solar/insolation_period.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"

namespace ts::solar {
namespace {

using namespace std::chrono;

year_month_day to_ymd(const CalendarDate& d) {
    return year_month_day{year{d.year}, month{unsigned(d.month)}, day{unsigned(d.day)}};
}

CalendarDate from_ymd(const year_month_day& ymd) {
    return {int(ymd.year()), int(unsigned(ymd.month())), int(unsigned(ymd.day()))};
}

microseconds clock_offset(double longitude_deg) {
    return microseconds(std::llround(longitude_deg / 15.0 * 3600.0 * 1e6));
}

std::string date_label(const CalendarDate& d) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%04d-%02d-%02d", d.year, d.month, d.day);
    return buf;
}

}  // namespace

CalendarDate parse_calendar_date(const std::string& text, const std::string& what) {
    int y = 0, m = 0, d = 0;
    char tail = 0;
    if (text.size() != 10 || std::sscanf(text.c_str(), "%4d-%2d-%2d%c", &y, &m, &d, &tail) != 3 || text[4] != '-' ||
        text[7] != '-')
        throw InputError(what + ": '" + text + "' is not a date YYYY-MM-DD");
    const year_month_day ymd{year{y}, month{unsigned(m)}, day{unsigned(d)}};
    if (y < 1 || !ymd.ok()) throw InputError(what + ": '" + text + "' is not a calendar date");
    return {y, m, d};
}

PeriodSplit parse_period_split(const std::string& text) {
    if (text == "year") return PeriodSplit::year;
    if (text == "month") return PeriodSplit::month;
    if (text == "day") return PeriodSplit::day;
    throw QuantityError(ts::Quantity::period_split, "", "'" + text + "' (choose year, month or day)");
}

light::UtcTime local_midnight(const CalendarDate& date, double longitude_deg) {
    const sys_days day_start{to_ymd(date)};
    return light::UtcTime(duration_cast<microseconds>(day_start.time_since_epoch())) - clock_offset(longitude_deg);
}

std::vector<InsolationPeriod> make_periods(const CalendarDate& first, const CalendarDate& last, PeriodSplit split,
                                           double longitude_deg) {
    const sys_days d0{to_ymd(first)}, d1{to_ymd(last)};
    if (d1 < d0) throw QuantityError(ts::Quantity::date_range, date_label(last), "is before the start, " + date_label(first));
    std::vector<InsolationPeriod> periods;
    sys_days start = d0;
    while (start <= d1) {
        const year_month_day ymd{start};
        sys_days unit_begin = start, unit_end = start + days(1);
        if (split == PeriodSplit::year) {
            unit_begin = sys_days{ymd.year() / January / 1};
            unit_end = sys_days{(ymd.year() + years(1)) / January / 1};
        } else if (split == PeriodSplit::month) {
            unit_begin = sys_days{ymd.year() / ymd.month() / 1};
            unit_end = sys_days{(ymd.year() / ymd.month() + months(1)) / 1};
        }
        const sys_days end = std::min(unit_end, d1 + days(1));
        InsolationPeriod p;
        p.begin = local_midnight(from_ymd(year_month_day{start}), longitude_deg);
        p.end = local_midnight(from_ymd(year_month_day{end}), longitude_deg);
        const CalendarDate a = from_ymd(year_month_day{start}), b = from_ymd(year_month_day{end - days(1)});
        char buf[32];
        if (start == unit_begin && end == unit_end && split == PeriodSplit::year)
            std::snprintf(buf, sizeof buf, "%04d", a.year), p.label = buf;
        else if (start == unit_begin && end == unit_end && split == PeriodSplit::month)
            std::snprintf(buf, sizeof buf, "%04d-%02d", a.year, a.month), p.label = buf;
        else if (end - start == days(1))
            p.label = date_label(a);
        else
            p.label = date_label(a) + ".." + date_label(b);
        periods.push_back(p);
        start = end;
    }
    return periods;
}

LocalDay local_day(light::UtcTime t, double longitude_deg) {
    const auto local = t + clock_offset(longitude_deg);
    const sys_days day = floor<days>(local);
    const year_month_day ymd{day};
    const sys_days jan1{ymd.year() / January / 1};
    return {int(unsigned(ymd.month())) - 1, int((day - jan1).count()) + 1};
}

}  // namespace ts::solar
