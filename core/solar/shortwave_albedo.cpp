#include "core/solar/shortwave_albedo.hpp"

namespace ts::solar {

float worldcover_shortwave_albedo(std::uint8_t code, float fallback) {
    switch (code) {
        case 10: return 0.13f;   // tree cover: coniferous 0.05-0.15, deciduous 0.15-0.20
        case 20: return 0.18f;   // shrubland
        case 30: return 0.21f;   // grassland: 0.16-0.26
        case 40: return 0.21f;   // cropland: 0.18-0.25
        case 50: return 0.15f;   // built-up: 0.10-0.27, typical cities ~0.15
        case 60: return 0.30f;   // bare or sparse vegetation: soils, rock, desert sand 0.20-0.45
        case 70: return 0.60f;   // snow and ice: old snow 0.40-0.70, fresh 0.80-0.95, ice 0.2-0.4
        case 80: return 0.07f;   // permanent water: 0.03-0.10 under a high sun
        case 90: return 0.14f;   // herbaceous wetland
        case 95: return 0.12f;   // mangroves
        case 100: return 0.20f;  // moss and lichen: tundra 0.18-0.25
        default: return fallback;
    }
}

std::vector<float> shortwave_albedo_of(std::span<const std::uint8_t> codes, float fallback) {
    std::vector<float> a(codes.size());
    for (std::size_t i = 0; i < codes.size(); ++i) a[i] = worldcover_shortwave_albedo(codes[i], fallback);
    return a;
}

}  // namespace ts::solar
