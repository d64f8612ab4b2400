#include "app/tile_set_viewer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "app/lightable_page.hpp"
#include "core/fly/bitmap_font.hpp"
#include "core/solar/insolation_model.hpp"
#include "core/tiles/svf_stretch.hpp"
#include "core/tiles/tile_viewer.hpp"
#include "core/util/error.hpp"
#include "core/util/staged_outputs.hpp"

namespace ts::app {
namespace {

namespace fs = std::filesystem;

std::string date_text(const solar::CalendarDate& d) {
    char text[32];
    std::snprintf(text, sizeof text, "%04d-%02d-%02d", d.year, d.month, d.day);
    return text;
}

// "global irradiation 2024" or "hours of direct sun 2024-06-20..2024-06-21".
std::string insolation_title(const TilesArgs& a, int quantity) {
    const char* what[] = {"global irradiation", "beam irradiation", "diffuse irradiation", "reflected irradiation",
                          "hours of direct sun"};
    const auto [first, last] = insolation_dates(a.insolation);
    const std::string days = a.insolation.year ? std::to_string(a.insolation.year)
                                               : date_text(first) + ".." + date_text(last);
    return std::string(what[quantity]) + " " + days;
}

// "elevation data: " and who made the heights as the DEM says (dem::Dem::credit), else the
// files' names (text: escaped, as the attribution may be read as HTML).
std::string default_attribution(const std::vector<std::string>& files, const std::string& credit) {
    if (!credit.empty()) return "elevation data: " + tiles::html_text(credit);
    std::string names;
    const std::size_t shown = std::min<std::size_t>(files.size(), 3);
    for (std::size_t i = 0; i < shown; ++i) names += (i ? ", " : "") + fs::path(files[i]).filename().string();
    if (files.size() > shown) names += " and " + std::to_string(files.size() - shown) + " more";
    return "elevation data: " + tiles::html_text(names);
}

void write_text(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw input_error(path.string(), "cannot write (disk full?)");
}

}  // namespace

std::optional<Legend> tile_set_legend(const TilesArgs& a, const tiles::TileJob& job) {
    const tiles::TileShading& s = job.shading;
    if (s.style->name() == "insolation" && s.insolation) {
        const int q = s.insolation->quantity;
        return Legend{insolation_title(a, q), solar::quantity_unit(q), s.insolation->lo, s.insolation->hi, inferno_ramp};
    }
    if (s.style->name() == "svf") return Legend{"sky view factor", "", tiles::kSvfBlack, 1.0f, grey_ramp};
    if (s.style->name() == "color") {
        // The palette's colours by height (fitted to the job's heights), over its stops' range.
        const render::Palette& p = s.colors.palette;
        const float lo = float(p.stops().front().value), hi = float(p.stops().back().value);
        const std::string name = fs::path(p.name()).filename().string();
        std::string title = "land colour by height (" + (name.empty() ? std::string("palette") : name) + ")";
        if (s.colors.snow_line_m) title += ", snow above " + std::to_string(int(std::lround(*s.colors.snow_line_m))) + " m";
        return Legend{title, "m", lo, hi, [p, lo, hi](float x, std::uint8_t* rgb) {
                          const glm::vec3 c = p.srgb_at(lo + double(x) * (hi - lo));
                          for (int k = 0; k < 3; ++k) rgb[k] = std::uint8_t(std::lround(std::clamp(c[k], 0.0f, 255.0f)));
                      }};
    }
    return std::nullopt;
}

tiles::TileSetInfo tile_set_info(const std::string& name, const std::string& attribution,
                                 const std::vector<std::string>& dem_files, const dem::Dem& dem,
                                 const tiles::TileJob& job, const std::optional<Legend>& legend) {
    const std::string style(job.shading.style->name());
    tiles::TileSetInfo info;
    info.name = name.empty() ? fs::path(dem_files.front()).stem().string() + " " + style : name;
    info.description = "terrashade " + style + ", " + std::to_string(job.tile_size) + "-px tiles";
    if (legend) info.description += ": " + legend->title + (legend->unit.empty() ? "" : " (" + legend->unit + ")");
    info.attribution = attribution.empty() ? default_attribution(dem_files, dem.credit) : attribution;
    info.bounds = tiles::terrain_footprint(dem);  // the terrain, not a nodata collar
    info.minzoom = job.z0, info.maxzoom = job.z1;
    info.tile_size = job.tile_size;
    if (legend) info.legend_file = tiles::kLegendFile, info.legend_alt = info.description;
    return info;
}

void write_tile_viewer(const std::string& dir, const tiles::TileSetInfo& info, const std::optional<Legend>& legend,
                       const std::string& lightable) {
    StagedOutputs outputs;
    const fs::path d(dir);
    outputs.stage(d / tiles::kTileJsonFile, [&](const fs::path& tmp) { write_text(tmp, tiles::tilejson_text(info)); });
    if (lightable.empty()) {
        outputs.stage(d / tiles::kViewerPageFile,
                      [&](const fs::path& tmp) { write_text(tmp, tiles::viewer_page_html(info)); });
    } else {
        // Data tiles are not pictures: their page relights them (app/web, embedded).
        for (auto& [name, text] : lightable_viewer_files(info))
            outputs.stage(d / name, [&, text = text](const fs::path& tmp) { write_text(tmp, text); });
    }
    if (legend) {
        // Wide enough for the title in the legend's bitmap font.
        const int width = std::max(320, int(legend->title.size()) * fly::kGlyphAdvance + 8);
        outputs.stage(d / tiles::kLegendFile, [&](const fs::path& tmp) { write_legend_png(tmp.string(), width, *legend); });
    }
    if (!lightable.empty())
        outputs.stage(d / tiles::kLightableFile, [&](const fs::path& tmp) { write_text(tmp, lightable); });
    outputs.commit();
}

}  // namespace ts::app
