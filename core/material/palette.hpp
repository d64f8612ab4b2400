#pragma once
// Colour by design: a map's land colours come from a palette of height stops, never from a guess
// about land cover. The text format is gdaldem color-relief's, so a palette made for GDAL works
// here unchanged (docs/colors.md):
//   <height> <R> <G> <B> [<A>]    one stop per line; R G B in 0..255 (sRGB), A read and ignored
//   <N>%      ...                 a stop at N% of the DEM's height range (0% its lowest, 100% its highest)
//   nv        ...                 the colour of no-data (read; voids are water here, see palette_materials.hpp)
// Fields may be separated by spaces, tabs or commas; blank lines and lines starting with '#'
// are skipped. Between stops the colour is interpolated linearly in sRGB (as gdaldem does),
// beyond the first and last stops it is held.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace ts::render {

struct PaletteStop {
    double value = 0;      // metres, or percent of the height range when `percent`
    bool percent = false;
    glm::vec3 srgb{0.0f};  // 0..255
};

// A palette's colour is what open flat ground looks like at a normal exposure; its albedo is that
// colour's linear value times this, so the pale tints cartographers use (sRGB ~160..215, linear
// ~0.35..0.68) become the albedos of vegetated and bare land (~0.12..0.24), and the default
// palette's white (sRGB 255) would be 0.35, bright dry ground, never snow (snow is --snow-line).
inline constexpr float kPaletteAlbedoScale = 0.35f;

class Palette {
public:
    // The built-in palettes by name ("hypsometric", "grey", "grey:A" of linear albedo A), or
    // nullopt; throws ts::InputError for grey:A with A not in [0, 1].
    static std::optional<Palette> named(std::string_view name);
    // Parses gdaldem color-relief text; `source` names it in errors ("FILE: line 3: ...").
    // Throws ts::InputError for a malformed line or no stop at all.
    static Palette parse(std::string_view text, const std::string& source);
    // Reads and parses a file; throws ts::InputError if it cannot be read.
    static Palette read(const std::filesystem::path& path);

    // The same palette with percent stops placed on [lowest, highest] metres (the whole job's
    // range, so that crops, tiles and blocks of one DEM get one colour per height).
    Palette fitted(double lowest_m, double highest_m) const;
    // The same (fitted) palette with the bathymetric tints of the cartographic tradition below
    // 0 m, light blue at the shore to deep blue at `deepest_m` (docs/colors.md); stops below 0 m
    // it had are replaced.
    Palette with_sea_tints(double deepest_m) const;
    bool has_percent_stops() const;

    // The sRGB colour (0..255) at a height; stops with percent are read as if fitted to [0, 100].
    glm::vec3 srgb_at(double height_m) const;
    // The linear albedo of land at a height: the colour's linear value times kPaletteAlbedoScale
    // (grey:A: times A).
    glm::vec3 albedo_at(double height_m) const;

    const std::vector<PaletteStop>& stops() const { return stops_; }
    const std::string& name() const { return name_; }
    // A canonical text of the stops (what a job records to tell palettes apart).
    std::string describe() const;

private:
    std::string name_;
    std::vector<PaletteStop> stops_;  // sorted by value
    float albedo_scale_ = kPaletteAlbedoScale;
};

// The default palette's name, and the names `named` knows, as "hypsometric, grey".
inline constexpr std::string_view kDefaultPalette = "hypsometric";
std::string palette_names();

}  // namespace ts::render
