// parse_sky_options: the --sky grammar of sky.hpp.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/light/sky.hpp"
#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"

namespace ts::light {

namespace {

const char* const kGrammar =
    "expected clear[:turbidity=T,albedo=A,scattering=multiple|single,aureole=DEG] (or physical[:...]), "
    "preetham[:turbidity=T,albedo=A], overcast[:brightness=B,albedo=A], PATH.exr, PATH.hdr or "
    "hdr:PATH[,rotation=DEG,scale=S]";

QuantityError sky_error(const std::string& problem) {
    return QuantityError(Quantity::sky, "", problem);
}

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

double parse_number(std::string_view key, std::string_view text) {
    double value = 0.0;
    const char* first = text.data();
    const char* last = text.data() + text.size();
    const auto [end, ec] = std::from_chars(first, last, value);
    if (text.empty() || ec != std::errc() || end != last || !std::isfinite(value)) {
        throw sky_error(std::string(key) + " must be a number, got '" + std::string(text) + "'");
    }
    return value;
}

std::string format_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

void check_range(std::string_view key, double value, double lo, double hi) {
    if (value < lo || value > hi) {
        throw sky_error(std::string(key) + " must be in " + format_number(lo) + ".." + format_number(hi) + ", got " +
                        format_number(value));
    }
}

struct KeyValue {
    std::string key;
    std::string value;
};

// "k=v,k=v" -> pairs; an item without '=' is an error.
std::vector<KeyValue> split_parameters(std::string_view text) {
    std::vector<KeyValue> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = text.find(',', start);
        const std::string_view item =
            text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
        const std::size_t eq = item.find('=');
        if (eq == std::string_view::npos || eq == 0) {
            throw sky_error("bad parameter '" + std::string(item) + "' (want key=value)");
        }
        out.push_back({lower(item.substr(0, eq)), std::string(item.substr(eq + 1))});
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    return out;
}

bool has_hdr_extension(const std::string& path) {
    const std::string l = lower(path);
    auto ends = [&](const char* ext) {
        const std::string e(ext);
        return l.size() > e.size() && l.compare(l.size() - e.size(), e.size(), e) == 0;
    };
    return ends(".exr") || ends(".hdr");
}

// An HDR spec: PATH[,rotation=DEG,scale=S]. Options are taken from the right while they look
// like one of ours, so a path may itself contain commas.
SkyOptions parse_hdr(std::string_view text, bool explicit_prefix) {
    SkyOptions o;
    o.kind = SkyOptions::Kind::hdr;
    std::string path(text);
    bool seen_rotation = false;
    bool seen_scale = false;
    for (;;) {
        const std::size_t comma = path.rfind(',');
        if (comma == std::string::npos) break;
        const std::string item = path.substr(comma + 1);
        const std::size_t eq = item.find('=');
        if (eq == std::string::npos) break;
        const std::string key = lower(item.substr(0, eq));
        const std::string value = item.substr(eq + 1);
        if (key == "rotation" && !seen_rotation) {
            o.hdr_rotation_deg = parse_number("rotation", value);
            seen_rotation = true;
        } else if (key == "scale" && !seen_scale) {
            o.hdr_scale = parse_number("scale", value);
            if (!(o.hdr_scale > 0.0)) throw sky_error("scale must be > 0, got " + value);
            seen_scale = true;
        } else {
            throw sky_error("unknown HDR parameter '" + key + "' (rotation=DEG, scale=S)");
        }
        path.erase(comma);
    }
    if (path.empty()) throw sky_error("no HDR map path given");
    if (!explicit_prefix && !has_hdr_extension(path)) {
        throw sky_error("unknown sky '" + path + "'; " + kGrammar);
    }
    o.hdr_path = path;
    return o;
}

}  // namespace

SkyOptions parse_sky_options(std::string_view text) {
    if (text.empty()) throw sky_error(std::string("empty; ") + kGrammar);
    const std::size_t colon = text.find(':');
    const std::string model = lower(text.substr(0, colon));
    const std::string_view rest = colon == std::string_view::npos ? std::string_view() : text.substr(colon + 1);
    if (model == "hdr") return parse_hdr(rest, true);
    if (model != "clear" && model != "physical" && model != "preetham" && model != "overcast") return parse_hdr(text, false);

    SkyOptions o;
    o.kind = model == "preetham"   ? SkyOptions::Kind::preetham
             : model == "overcast" ? SkyOptions::Kind::overcast
                                   : SkyOptions::Kind::physical;
    if (colon == std::string_view::npos) return o;
    if (rest.empty()) throw sky_error("nothing after '" + model + ":'");
    for (const KeyValue& kv : split_parameters(rest)) {
        if (kv.key == "albedo") {
            o.ground_albedo = parse_number("albedo", kv.value);
            check_range("albedo", o.ground_albedo, 0.0, 1.0);
        } else if (kv.key == "turbidity" && o.kind != SkyOptions::Kind::overcast) {
            o.turbidity = parse_number("turbidity", kv.value);
            check_range("turbidity", o.turbidity, 1.7, 10.0);
        } else if (kv.key == "scattering" && o.kind == SkyOptions::Kind::physical) {
            const std::string v = lower(kv.value);
            if (v != "multiple" && v != "single") throw sky_error("scattering must be multiple or single, got '" + kv.value + "'");
            o.multiple_scattering = v == "multiple";
        } else if (kv.key == "aureole" && o.kind == SkyOptions::Kind::physical) {
            o.aureole_deg = parse_number("aureole", kv.value);
            o.aureole_given = true;
            check_range("aureole", o.aureole_deg, 0.0, 90.0);
        } else if (kv.key == "brightness" && o.kind == SkyOptions::Kind::overcast) {
            o.overcast_brightness = parse_number("brightness", kv.value);
            if (!(o.overcast_brightness > 0.0) || o.overcast_brightness > 1000.0) {
                throw sky_error("brightness must be in (0, 1000], got " + kv.value);
            }
        } else {
            throw sky_error("unknown parameter '" + kv.key + "' for " + model + " (" + kGrammar + ")");
        }
    }
    return o;
}

}  // namespace ts::light
