#include "core/tiles/tile_style.hpp"

#include <stdexcept>
#include <string>

#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"

namespace ts::tiles {

// Each style's file defines its function; a new style is registered with one line in the list.
const TileStyle& relief_tile_style();
const TileStyle& hillshade_tile_style();
const TileStyle& multidirectional_tile_style();
const TileStyle& svf_tile_style();
const TileStyle& color_tile_style();
const TileStyle& insolation_tile_style();
const TileStyle& lightable_tile_style();

const std::vector<const TileStyle*>& tile_styles() {
    static const std::vector<const TileStyle*> styles = {
        &relief_tile_style(),
        &hillshade_tile_style(),
        &multidirectional_tile_style(),
        &svf_tile_style(),
        &color_tile_style(),
        &insolation_tile_style(),
        &lightable_tile_style(),
    };
    return styles;
}

const TileStyle* find_tile_style(std::string_view name) {
    for (const TileStyle* s : tile_styles())
        if (s->name() == name) return s;
    return nullptr;
}

const TileStyle& default_tile_style() { return relief_tile_style(); }

std::string tile_style_names(std::string_view separator) {
    std::string out;
    for (const TileStyle* s : tile_styles()) out += (out.empty() ? "" : std::string(separator)) + std::string(s->name());
    return out;
}

const TileStyle& parse_tile_style(std::string_view text) {
    if (const TileStyle* s = find_tile_style(text)) return *s;
    // "relief, hillshade, multidirectional, svf, color or insolation"
    const std::vector<const TileStyle*>& all = tile_styles();
    std::string names;
    for (std::size_t i = 0; i < all.size(); ++i)
        names += (i == 0 ? "" : i + 1 == all.size() ? " or " : ", ") + std::string(all[i]->name());
    throw QuantityError(Quantity::tile_style, std::string(text), "use " + names);
}

// A style overrides the one its uses_visibility() calls for; reaching these is a bug.
void TileStyle::shade_tile(const TileFrame&, const std::vector<float>&, double, const HornLight&, const std::uint8_t*,
                           std::uint8_t*) const {
    throw std::logic_error("tile style " + std::string(name()) + " shades no tile from heights");
}

std::vector<float> TileStyle::shade_block(const BlockShading&) const {
    throw std::logic_error("tile style " + std::string(name()) + " shades no block from visibility");
}

Resampling parse_resampling(std::string_view text) {
    if (text == "bilinear") return Resampling::bilinear;
    if (text == "cubic") return Resampling::cubic;
    throw QuantityError(Quantity::resampling, std::string(text), "use bilinear or cubic");
}

std::string_view resampling_name(Resampling r) { return r == Resampling::cubic ? "cubic" : "bilinear"; }

FarFieldMethod parse_far_field(std::string_view text) {
    for (FarFieldMethod m : {FarFieldMethod::exact, FarFieldMethod::fast, FarFieldMethod::balanced, FarFieldMethod::fine,
                             FarFieldMethod::finest})
        if (text == far_field_name(m)) return m;
    throw QuantityError(Quantity::far_field, std::string(text), "use exact, fast, balanced, fine or finest");
}

std::string_view far_field_name(FarFieldMethod m) {
    switch (m) {
        case FarFieldMethod::exact: return "exact";
        case FarFieldMethod::fast: return "fast";
        case FarFieldMethod::balanced: return "balanced";
        case FarFieldMethod::fine: return "fine";
        case FarFieldMethod::finest: return "finest";
    }
    return "?";
}

int far_field_samples_per_octave(FarFieldMethod m) {
    switch (m) {
        case FarFieldMethod::exact: return 0;
        case FarFieldMethod::fast: return 2;
        case FarFieldMethod::balanced: return 4;
        case FarFieldMethod::fine: return 8;
        case FarFieldMethod::finest: return 16;
    }
    return 0;
}

}  // namespace ts::tiles
