#include "core/tiles/tile_style.hpp"

#include <string>

#include "core/util/error.hpp"

namespace ts::tiles {

TileStyle parse_tile_style(std::string_view text) {
    for (TileStyle s : {TileStyle::relief, TileStyle::hillshade, TileStyle::multidirectional, TileStyle::svf,
                        TileStyle::color})
        if (text == tile_style_name(s)) return s;
    throw InputError("--style " + std::string(text) + ": use relief, hillshade, multidirectional, svf or color");
}

std::string_view tile_style_name(TileStyle s) {
    switch (s) {
        case TileStyle::relief: return "relief";
        case TileStyle::hillshade: return "hillshade";
        case TileStyle::multidirectional: return "multidirectional";
        case TileStyle::svf: return "svf";
        case TileStyle::color: return "color";
    }
    return "?";
}

Resampling parse_resampling(std::string_view text) {
    if (text == "bilinear") return Resampling::bilinear;
    if (text == "cubic") return Resampling::cubic;
    throw InputError("--resampling " + std::string(text) + ": use bilinear or cubic");
}

std::string_view resampling_name(Resampling r) { return r == Resampling::cubic ? "cubic" : "bilinear"; }

FarFieldMethod parse_far_field(std::string_view text) {
    for (FarFieldMethod m : {FarFieldMethod::exact, FarFieldMethod::fast, FarFieldMethod::balanced, FarFieldMethod::fine,
                             FarFieldMethod::finest})
        if (text == far_field_name(m)) return m;
    throw InputError("--far-field " + std::string(text) + ": use exact, fast, balanced, fine or finest");
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
