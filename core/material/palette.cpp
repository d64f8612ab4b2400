#include "core/material/palette.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/raster/srgb.hpp"
#include "core/util/quantity_error.hpp"
#include "core/util/error.hpp"

namespace ts::render {
namespace {

// Hypsometric tints in the Swiss/Imhof tradition, fitted to the DEM's range: grey-green
// lowlands, pale yellow and light tan uplands, light warm grey summits. All of one luminance
// (linear Y 0.557-0.561): the hue tells the height and only light and shadow change the
// brightness, so the map reads as the relief a uniform grey terrain shows, under a sun and under
// an overcast sky alike (where tints that grew lighter with height, 1.27x, took the overcast
// map's correlation with the grey one down to 0.56). No white-blue, which reads as snow.
constexpr std::string_view kHypsometric =
    "0%   175 206 162\n"
    "20%  184 204 155\n"
    "45%  200 200 158\n"
    "70%  211 195 169\n"
    "88%  204 196 188\n"
    "100% 199 197 193\n";
// One grey (linear albedo 0.18 after kPaletteAlbedoScale): pure relief.
constexpr std::string_view kGrey = "0% 190 190 190\n";

std::string trim(std::string_view s) {
    std::size_t a = 0, b = s.size();
    while (a < b && (s[a] == ' ' || s[a] == '\t' || s[a] == '\r')) ++a;
    while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t' || s[b - 1] == '\r')) --b;
    return std::string(s.substr(a, b - a));
}

std::vector<std::string> fields_of(const std::string& line) {
    std::vector<std::string> out;
    std::string cur;
    for (char ch : line) {
        if (ch == ' ' || ch == '\t' || ch == ',') {
            if (!cur.empty()) out.push_back(cur), cur.clear();
        } else {
            cur += ch;
        }
    }
    if (!cur.empty()) out.push_back(cur);
    return out;
}

bool parse_double(const std::string& s, double& out) {
    const char* end = s.data() + s.size();
    const auto r = std::from_chars(s.data(), end, out);
    return r.ec == std::errc() && r.ptr == end && std::isfinite(out);
}

std::string number(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

}  // namespace

std::string palette_names() { return "hypsometric, grey, grey:ALBEDO"; }

std::optional<Palette> Palette::named(std::string_view name) {
    std::optional<Palette> p;
    if (name == "hypsometric") p = parse(kHypsometric, "hypsometric");
    if (name == "grey" || name == "gray") p = parse(kGrey, "grey");
    if (p) p->name_ = std::string(name == "gray" ? "grey" : name);
    // grey:A, one grey of linear albedo A in [0, 1] (0.8 for snow, as a path tracer's scene has it):
    // white stops scaled by A rather than kPaletteAlbedoScale.
    for (std::string_view prefix : {"grey:", "gray:"}) {
        if (name.substr(0, prefix.size()) != prefix) continue;
        double a = 0;
        if (!parse_double(std::string(name.substr(prefix.size())), a) || a < 0 || a > 1)
            throw QuantityError(Quantity::palette, std::string(name), "grey:A takes a linear albedo A in [0, 1]");
        p = parse("0% 255 255 255\n", "grey");
        p->albedo_scale_ = float(a);
        p->name_ = "grey:" + number(a);
    }
    return p;
}

Palette Palette::parse(std::string_view text, const std::string& source) {
    for (unsigned char ch : text)
        if (ch < 0x20 && ch != '\t' && ch != '\r' && ch != '\n')
            throw InputError(source + ": not a colour table (gdaldem color-relief text: HEIGHT R G B per line)");
    Palette p;
    p.name_ = source;
    std::size_t pos = 0;
    int line_no = 0;
    while (pos <= text.size()) {
        const std::size_t nl = text.find('\n', pos);
        const std::string line = trim(text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos));
        pos = nl == std::string_view::npos ? text.size() + 1 : nl + 1;
        ++line_no;
        if (line.empty() || line[0] == '#') continue;
        const auto where = [&] { return source + ": line " + std::to_string(line_no) + ": "; };
        const std::vector<std::string> f = fields_of(line);
        if (f.size() < 4 || f.size() > 5)
            throw InputError(where() + "give HEIGHT R G B [A] (HEIGHT in metres, N% or nv; R G B in 0..255)");
        if (f[0] == "nv" || f[0] == "NV") continue;  // no-data: voids are water here
        PaletteStop stop;
        std::string value = f[0];
        if (!value.empty() && value.back() == '%') {
            stop.percent = true;
            value.pop_back();
        }
        if (!parse_double(value, stop.value))
            throw InputError(where() + "'" + f[0] + "' is not a height (metres, N% or nv)");
        if (stop.percent && (stop.value < 0 || stop.value > 100))
            throw InputError(where() + "'" + f[0] + "': a percentage of the height range must be within 0..100");
        for (int c = 0; c < 3; ++c) {
            double v = 0;
            if (!parse_double(f[std::size_t(c) + 1], v) || v < 0 || v > 255)
                throw InputError(where() + "'" + f[std::size_t(c) + 1] +
                                 "' is not a colour component (R G B are numbers in 0..255; colour names are not read)");
            stop.srgb[c] = float(v);
        }
        if (f.size() == 5) {
            double a = 0;
            if (!parse_double(f[4], a) || a < 0 || a > 255)
                throw InputError(where() + "'" + f[4] + "' is not an alpha in 0..255");
        }
        p.stops_.push_back(stop);
    }
    if (p.stops_.empty()) throw InputError(source + ": no colour stop (gdaldem color-relief text: HEIGHT R G B per line)");
    std::stable_sort(p.stops_.begin(), p.stops_.end(), [](const PaletteStop& a, const PaletteStop& b) {
        if (a.percent != b.percent) return a.percent;  // an unfitted mix: percent stops first
        return a.value < b.value;
    });
    return p;
}

Palette Palette::read(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string() + ": cannot read the colour table");
    std::ostringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    if (s.size() > (std::size_t(1) << 20)) throw InputError(path.string() + ": a colour table larger than 1 MB");
    Palette p = parse(s, path.string());
    return p;
}

bool Palette::has_percent_stops() const {
    return std::any_of(stops_.begin(), stops_.end(), [](const PaletteStop& s) { return s.percent; });
}

Palette Palette::fitted(double lowest_m, double highest_m) const {
    Palette p = *this;
    if (!(highest_m > lowest_m)) highest_m = lowest_m + 1.0;  // a flat DEM: one colour anyway
    for (PaletteStop& s : p.stops_)
        if (s.percent) {
            s.value = lowest_m + (highest_m - lowest_m) * s.value / 100.0;
            s.percent = false;
        }
    std::stable_sort(p.stops_.begin(), p.stops_.end(),
                     [](const PaletteStop& a, const PaletteStop& b) { return a.value < b.value; });
    return p;
}

Palette Palette::with_sea_tints(double deepest_m) const {
    Palette p = *this;
    std::erase_if(p.stops_, [](const PaletteStop& s) { return !s.percent && s.value < 0.0; });
    // Light blue at the shore, deepening over the first third of the depth (shelves and slopes,
    // where the sea floor's relief is), then to deep blue on the abyssal plains.
    const double deep = std::min(deepest_m, -1.0);
    const PaletteStop sea[] = {{deep, false, {112, 150, 196}}, {0.3 * deep, false, {160, 196, 222}}, {0.0, false, {190, 218, 232}}};
    p.stops_.insert(p.stops_.begin(), std::begin(sea), std::end(sea));
    // Stable: the sea's 0 m stop stays before the land's, so 0 m itself is land.
    std::stable_sort(p.stops_.begin(), p.stops_.end(),
                     [](const PaletteStop& a, const PaletteStop& b) { return a.value < b.value; });
    return p;
}

glm::vec3 Palette::srgb_at(double h) const {
    if (stops_.empty() || std::isnan(h)) return glm::vec3(0.0f);
    if (h <= stops_.front().value) return stops_.front().srgb;
    if (h >= stops_.back().value) return stops_.back().srgb;
    const auto hi = std::upper_bound(stops_.begin(), stops_.end(), h,
                                     [](double v, const PaletteStop& s) { return v < s.value; });
    const auto lo = hi - 1;
    const double span = hi->value - lo->value;
    const float t = span > 0 ? float((h - lo->value) / span) : 1.0f;
    return lo->srgb + (hi->srgb - lo->srgb) * t;
}

glm::vec3 Palette::albedo_at(double h) const {
    const glm::vec3 c = srgb_at(h) / 255.0f;
    return glm::vec3(raster::srgb_eotf(c.x), raster::srgb_eotf(c.y), raster::srgb_eotf(c.z)) * albedo_scale_;
}

std::string Palette::describe() const {
    std::string s = albedo_scale_ == kPaletteAlbedoScale ? "" : "albedo " + number(albedo_scale_);
    for (const PaletteStop& stop : stops_) {
        if (!s.empty()) s += ";";
        s += number(stop.value) + (stop.percent ? "%" : "") + " " + number(stop.srgb.x) + " " + number(stop.srgb.y) +
             " " + number(stop.srgb.z);
    }
    return s;
}

}  // namespace ts::render
