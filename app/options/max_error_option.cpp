#include "app/options/max_error_option.hpp"

#include "core/util/error.hpp"

namespace ts::app {

void add_max_error_option(CLI::App& cmd, std::optional<double>& max_error) {
    cmd.add_option("--max-error", max_error,
                   "Adaptive quality: the cheapest --directions (and sun shadows) predicted to keep the relative "
                   "radiance error (RMSE / mean against the ray-traced reference) under E > 0 for this terrain and "
                   "sun, e.g. 0.05; prints what it chose and why (docs/accuracy.md)");
}

void check_max_error(const std::optional<double>& max_error, const std::string& given) {
    if (!max_error) return;
    if (!(*max_error > 0)) throw InputError("--max-error must be > 0 (a relative radiance error, e.g. 0.05 for 5%)");
    if (!given.empty()) throw InputError("--max-error chooses " + given + " itself; drop one of them");
}

std::string max_error_line(const std::string& reason) {
    // core's reason starts with the bound ("0.05: 32 directions, ..."), so the flag goes first.
    return "--max-error " + reason;
}

}  // namespace ts::app
