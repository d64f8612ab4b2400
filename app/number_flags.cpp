#include "app/number_flags.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>

#include "core/util/error.hpp"

namespace ts::app {
namespace {

enum class NumberKind { none, integer, real };

// CLI11 names an option's value type INT, UINT or FLOAT (then ":" and its checks' descriptions);
// options with a type name of their own (W,S,E,N ...) parse their text themselves.
NumberKind kind_of(const CLI::Option& opt) {
    const std::string type = opt.get_type_name();
    const std::string_view base = std::string_view(type).substr(0, type.find(':'));
    if (base == "INT" || base == "UINT") return NumberKind::integer;
    if (base == "FLOAT") return NumberKind::real;
    return NumberKind::none;
}

bool is_real(const std::string& text) {
    if (text.empty()) return false;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size() && std::isfinite(v);
}

bool is_integer(const std::string& text) {
    std::string_view s = text;
    if (s.starts_with('+')) s.remove_prefix(1);
    long long v = 0;
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    // Out of the type's range is a number still: the option's own check gives the range.
    return !s.empty() && p == s.data() + s.size() && (ec == std::errc() || ec == std::errc::result_out_of_range);
}

void check_number(const std::string& name, NumberKind kind, const std::string& text) {
    if (kind == NumberKind::integer && !is_integer(text))
        throw InputError(name + ": '" + text + "' is not " + (is_real(text) ? "a whole number" : "a number"));
    if (kind == NumberKind::real && !is_real(text)) throw InputError(name + ": '" + text + "' is not a number");
}

void add_check(CLI::Option& opt, NumberKind kind) {
    const std::string name = opt.get_name();
    // A list option (--elevations 10,20) reaches its checks before it is split.
    const char delimiter = opt.get_delimiter();
    opt.transform(CLI::Validator(
        [name, kind, delimiter](std::string& text) -> std::string {
            if (delimiter == '\0') {
                check_number(name, kind, text);
                return {};
            }
            std::size_t start = 0;
            for (;;) {
                const std::size_t end = text.find(delimiter, start);
                check_number(name, kind, text.substr(start, end - start));
                if (end == std::string::npos) return {};
                start = end + 1;
            }
        },
        ""));
}

}  // namespace

void explain_non_numbers(CLI::App& app) {
    for (CLI::Option* opt : app.get_options()) {
        const NumberKind kind = kind_of(*opt);
        if (kind != NumberKind::none) add_check(*opt, kind);
    }
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) explain_non_numbers(*sub);
}

}  // namespace ts::app
