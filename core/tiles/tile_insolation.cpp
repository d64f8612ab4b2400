#include "core/tiles/tile_insolation.hpp"

#include <algorithm>
#include <vector>


namespace ts::tiles {
namespace {

constexpr const char* kQuantityNames[solar::kQuantities] = {"global", "beam", "diffuse", "reflected", "sun-hours"};

}  // namespace

const char* insolation_quantity_name(int quantity) { return kQuantityNames[quantity]; }

double open_flat_insolation(const solar::InsolationModel& model, int quantity) {
    // Open flat ground: every horizon below the lowest the tables tell apart, the normal up.
    const std::vector<float> horizon(std::size_t(model.settings().azimuth_bins), -1.5f);
    std::vector<float> out(std::size_t(model.periods()) * solar::kQuantities);
    model.texel(horizon.data(), glm::vec3(0, 0, 1), model.bands() / 2, 0.0, out.data());
    double sum = 0;
    for (int p = 0; p < model.periods(); ++p) sum += out[std::size_t(p) * solar::kQuantities + std::size_t(quantity)];
    return sum;
}

RampEnds default_insolation_ramp(const solar::InsolationModel& model, int quantity) {
    if (quantity == solar::kReflected) {
        const double global = open_flat_insolation(model, solar::kGlobal);
        return {0.0f, float(std::max(1e-3, 0.3 * model.settings().albedo * global))};
    }
    const double flat = std::max(1e-3, open_flat_insolation(model, quantity));
    if (quantity == solar::kSunHours) return {0.0f, float(flat)};
    if (quantity == solar::kDiffuse) return {float(0.5 * flat), float(1.05 * flat)};
    return {float(0.4 * flat), float(1.3 * flat)};
}

}  // namespace ts::tiles
