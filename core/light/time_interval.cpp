#include "core/light/time_interval.hpp"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <string>

#include "core/util/error.hpp"

namespace ts::light {

namespace {

using std::chrono::microseconds;

[[noreturn]] void duration_error(std::string_view text, const std::string& problem) {
    throw input_error(std::string(text), problem + " (ISO 8601 duration examples: PT1H, PT15M, P1D)");
}

}  // namespace

microseconds parse_iso_duration(std::string_view text) {
    if (text.empty() || (text[0] != 'P' && text[0] != 'p')) duration_error(text, "a duration starts with P");
    // Designators in the order ISO 8601 allows them, with their length in microseconds.
    struct Unit {
        char designator;
        bool in_time_part;
        double micro;
    };
    constexpr Unit kUnits[] = {
        {'W', false, 7 * 86400e6}, {'D', false, 86400e6}, {'H', true, 3600e6}, {'M', true, 60e6}, {'S', true, 1e6}};
    std::size_t pos = 1, next_unit = 0;
    bool in_time = false, any_component = false, had_fraction = false;
    double total = 0.0;
    while (pos < text.size()) {
        if (text[pos] == 'T' || text[pos] == 't') {
            if (in_time) duration_error(text, "two 'T' separators");
            in_time = true;
            ++pos;
            if (pos == text.size()) duration_error(text, "nothing after 'T'");
            continue;
        }
        if (had_fraction) duration_error(text, "only the last component may have a fraction");
        const std::size_t start = pos;
        while (pos < text.size() && ((text[pos] >= '0' && text[pos] <= '9') || text[pos] == '.' || text[pos] == ','))
            ++pos;
        if (pos == start) duration_error(text, "expected a number");
        if (pos == text.size()) duration_error(text, "number without a designator (H, M, S, D, W)");
        std::string number(text.substr(start, pos - start));
        for (char& c : number)
            if (c == ',') c = '.';
        if (number.find('.') != number.rfind('.') || number.front() == '.' || number.back() == '.')
            duration_error(text, "malformed number '" + number + "'");
        had_fraction = number.find('.') != std::string::npos;
        const double value = std::stod(number);
        const char designator = static_cast<char>(std::toupper(static_cast<unsigned char>(text[pos])));
        ++pos;
        if (!in_time && (designator == 'Y' || designator == 'M'))
            duration_error(text, "years and months have no fixed length; use days (D) or weeks (W)");
        std::size_t u = next_unit;
        while (u < std::size(kUnits) && !(kUnits[u].designator == designator && kUnits[u].in_time_part == in_time)) ++u;
        if (u == std::size(kUnits))
            duration_error(text, std::string("unexpected or out-of-order '") + designator + "'");
        next_unit = u + 1;
        total += value * kUnits[u].micro;
        any_component = true;
    }
    if (!any_component) duration_error(text, "no components");
    if (!(total >= 1.0)) duration_error(text, "the duration must be at least one microsecond");
    if (total > 1e17) duration_error(text, "the duration is too long");
    return microseconds(static_cast<std::int64_t>(std::llround(total)));
}

std::vector<UtcTime> parse_time_interval(std::string_view text, std::size_t max_count) {
    const std::size_t first = text.find('/');
    const std::size_t second = first == std::string_view::npos ? first : text.find('/', first + 1);
    if (second == std::string_view::npos || text.find('/', second + 1) != std::string_view::npos)
        throw input_error(std::string(text), "expected START/END/STEP, e.g. 2024-06-21T04:00Z/2024-06-21T20:00Z/PT1H");
    const UtcTime start = parse_utc_time(text.substr(0, first));
    const UtcTime end = parse_utc_time(text.substr(first + 1, second - first - 1));
    const microseconds step = parse_iso_duration(text.substr(second + 1));
    if (end < start) throw input_error(std::string(text), "END is before START");
    const auto steps = (end - start) / step;  // whole steps that fit
    if (static_cast<std::uint64_t>(steps) + 1 > max_count)
        throw input_error(std::string(text), std::to_string(steps + 1) + " times, more than the limit of " +
                                                 std::to_string(max_count) + "; use a longer STEP");
    std::vector<UtcTime> times;
    times.reserve(static_cast<std::size_t>(steps) + 1);
    for (std::int64_t k = 0; k <= steps; ++k) times.push_back(start + k * step);
    return times;
}

}  // namespace ts::light
