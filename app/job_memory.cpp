#include "app/job_memory.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>

#include "core/util/error.hpp"
#include "core/util/memory.hpp"

namespace ts::app {
namespace {

constexpr std::uint64_t kProcessBytes = 64ull << 20;  // the binary, its libraries, small tables
constexpr double kMargin = 1.25;

std::uint64_t with_margin(double per_texel, std::uint64_t texels) {
    return kProcessBytes + std::uint64_t(std::ceil(kMargin * per_texel * double(texels)));
}

}  // namespace

std::uint64_t visibility_peak_bytes(std::uint64_t texels, int directions, bool sh_products) {
    return with_margin(4.0 * directions + 90.0 + (sh_products ? 110.0 : 0.0), texels);
}

std::uint64_t render_peak_bytes(std::uint64_t texels, int directions, bool meshes) {
    return with_margin(4.0 * directions + 310.0 + (meshes ? 64.0 : 0.0), texels);
}

void check_job_memory(const std::string& what, std::uint64_t bytes, const std::string& reduce) {
    const std::uint64_t available = available_memory();
    if (bytes <= available) return;
    throw InputError(what + " needs about " + format_bytes(bytes) + " of memory, " + format_bytes(available) +
                     " available" + (memory_cap() ? " (TERRASHADE_MEMORY_LIMIT)" : "") + ": " + reduce);
}

void apply_memory_limit_from_environment() {
    const char* text = std::getenv("TERRASHADE_MEMORY_LIMIT");
    if (!text || !*text) return;
    const std::string s(text);
    std::size_t used = 0;
    double value = 0;
    try {
        value = std::stod(s, &used);
    } catch (...) {
        used = 0;
    }
    std::string unit = s.substr(used);
    for (char& c : unit) c = char(std::toupper(static_cast<unsigned char>(c)));
    double scale = 0;
    if (unit.empty() || unit == "B") scale = 1;
    else if (unit == "KB" || unit == "K") scale = 1e3;
    else if (unit == "MB" || unit == "M") scale = 1e6;
    else if (unit == "GB" || unit == "G") scale = 1e9;
    else if (unit == "TB" || unit == "T") scale = 1e12;
    if (used == 0 || scale == 0 || !(value > 0) || !std::isfinite(value))
        throw InputError("TERRASHADE_MEMORY_LIMIT: '" + s + "' is not a size (e.g. 4GB, 512MB or bytes)");
    set_memory_cap(std::uint64_t(value * scale));
}

}  // namespace ts::app
