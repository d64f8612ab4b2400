#include "app/options/size_option.hpp"

#include <charconv>
#include <string_view>

#include "core/util/error.hpp"

namespace ts::app {

void parse_size(const std::string& text, const SizeRange& range, int& width, int& height) {
    const auto x = text.find_first_of("xX");
    auto side = [&](std::string_view s, int& out) {
        const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
        return ec == std::errc() && p == s.data() + s.size() && out >= range.min_side && out <= range.max_side;
    };
    if (x == std::string::npos || !side(std::string_view(text).substr(0, x), width) ||
        !side(std::string_view(text).substr(x + 1), height))
        throw InputError("--size " + text + ": give WIDTHxHEIGHT, each " + std::to_string(range.min_side) + ".." +
                         std::to_string(range.max_side) + " (e.g. " + range.example + ")");
}

}  // namespace ts::app
