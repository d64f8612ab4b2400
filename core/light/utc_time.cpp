#include "core/light/utc_time.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>

#include "core/util/error.hpp"

namespace ts::light {

namespace {

using namespace std::chrono;

// A cursor over the text being parsed; every failure names the whole input.
class Reader {
public:
    explicit Reader(std::string_view text) : text_(text) {}

    [[noreturn]] void fail(const std::string& problem) const {
        throw input_error(std::string(text_), problem + " (ISO 8601 example: 2024-06-21T12:00:00Z)");
    }
    bool at_end() const { return pos_ == text_.size(); }
    char peek() const { return at_end() ? '\0' : text_[pos_]; }
    bool accept(char c) {
        if (peek() != c) return false;
        ++pos_;
        return true;
    }
    void expect(char c, const char* what) {
        if (!accept(c)) fail(std::string("expected ") + what);
    }
    // Exactly `count` decimal digits.
    int digits(int count, const char* what) {
        int value = 0;
        for (int i = 0; i < count; ++i) {
            const char c = peek();
            if (c < '0' || c > '9') fail(std::string("expected ") + std::to_string(count) + "-digit " + what);
            value = value * 10 + (c - '0');
            ++pos_;
        }
        return value;
    }
    // One or more digits after a decimal mark, rounded to microseconds.
    std::int64_t fraction_microseconds() {
        std::int64_t micro = 0;
        int n = 0;
        bool round_up = false;
        while (peek() >= '0' && peek() <= '9') {
            const int d = peek() - '0';
            if (n < 6)
                micro = micro * 10 + d;
            else if (n == 6)
                round_up = d >= 5;
            ++n;
            ++pos_;
        }
        if (n == 0) fail("expected digits after the decimal mark");
        for (int i = n; i < 6; ++i) micro *= 10;
        return micro + (round_up ? 1 : 0);
    }

private:
    std::string_view text_;
    std::size_t pos_ = 0;
};

int days_in_month(int year, int month) {
    return static_cast<int>(static_cast<unsigned>(
        year_month_day_last(std::chrono::year(year), month_day_last(std::chrono::month(static_cast<unsigned>(month))))
            .day()));
}

}  // namespace

UtcTime parse_utc_time(std::string_view text) {
    Reader r(text);
    if (text.empty()) r.fail("empty time");
    const int y = r.digits(4, "year");
    r.expect('-', "'-' after the year");
    const int mo = r.digits(2, "month");
    r.expect('-', "'-' after the month");
    const int d = r.digits(2, "day");
    if (mo < 1 || mo > 12) r.fail("month " + std::to_string(mo) + " is not 01..12");
    if (d < 1 || d > days_in_month(y, mo)) r.fail("day " + std::to_string(d) + " does not exist in that month");
    if (r.at_end()) r.fail("a time of day and a zone (Z or +HH:MM) are required");
    if (!(r.accept('T') || r.accept('t') || r.accept(' '))) r.fail("expected 'T' between date and time");
    const int h = r.digits(2, "hour");
    r.expect(':', "':' after the hour");
    const int mi = r.digits(2, "minute");
    int s = 0;
    std::int64_t micro = 0;
    if (r.accept(':')) {
        s = r.digits(2, "second");
        if (r.accept('.') || r.accept(',')) micro = r.fraction_microseconds();
    }
    if (h > 23) r.fail("hour " + std::to_string(h) + " is not 00..23");
    if (mi > 59) r.fail("minute " + std::to_string(mi) + " is not 00..59");
    if (s > 60) r.fail("second " + std::to_string(s) + " is not 00..60");  // 60: a leap second
    int offset_minutes = 0;
    if (r.accept('Z') || r.accept('z')) {
    } else if (r.peek() == '+' || r.peek() == '-') {
        const int sign = r.peek() == '-' ? -1 : 1;
        r.accept(r.peek());
        const int oh = r.digits(2, "offset hour");
        int om = 0;
        if (r.accept(':'))
            om = r.digits(2, "offset minute");
        else if (!r.at_end())
            om = r.digits(2, "offset minute");
        if (oh > 23 || om > 59) r.fail("UTC offset out of range");
        offset_minutes = sign * (oh * 60 + om);
    } else if (r.at_end()) {
        r.fail("no zone: add Z for UTC or an offset such as +02:00");
    } else {
        r.fail("unexpected text after the time");
    }
    if (!r.at_end()) r.fail("unexpected text after the zone");

    const sys_days day = std::chrono::year(y) / std::chrono::month(static_cast<unsigned>(mo)) /
                         std::chrono::day(static_cast<unsigned>(d));
    // Local wall time minus the offset is UTC.
    return UtcTime(day) + hours(h) + minutes(mi) + seconds(s) + microseconds(micro) - minutes(offset_minutes);
}

std::string format_utc_time(UtcTime t) {
    const sys_days day = floor<days>(t);
    const year_month_day ymd(day);
    const hh_mm_ss<microseconds> hms(t - day);
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%04d-%02u-%02uT%02d:%02d:%02d", static_cast<int>(ymd.year()),
                  static_cast<unsigned>(ymd.month()), static_cast<unsigned>(ymd.day()),
                  static_cast<int>(hms.hours().count()), static_cast<int>(hms.minutes().count()),
                  static_cast<int>(hms.seconds().count()));
    std::string out = buffer;
    if (const auto us = hms.subseconds().count(); us != 0) {
        std::snprintf(buffer, sizeof buffer, ".%06lld", static_cast<long long>(us));
        std::string frac = buffer;
        while (frac.back() == '0') frac.pop_back();
        out += frac;
    }
    return out + "Z";
}

double julian_day(UtcTime t) {
    // Whole days and the day fraction apart, so the fraction keeps its microseconds.
    const sys_days day = floor<days>(t);
    const double fraction = duration<double, days::period>(t - day).count();
    return 2440587.5 + static_cast<double>(day.time_since_epoch().count()) + fraction;
}

double decimal_year(UtcTime t) {
    const year_month_day ymd(floor<days>(t));
    const sys_days start = ymd.year() / January / 1;
    const sys_days end = (ymd.year() + years(1)) / January / 1;
    return static_cast<int>(ymd.year()) + duration<double>(t - start).count() / duration<double>(end - start).count();
}

}  // namespace ts::light
