#pragma once
// The brute-force reference of InsolationModel::texel: the same model summed time step by time
// step, with the sun's visibility computed at each step from the horizon in the sun's own
// azimuth (linear between `horizons.size()` evenly spaced azimuths, given as finely as a test
// wants) and the ESRA terms at the texel's own height. Slow on purpose; for tests and studies.
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/solar/insolation_model.hpp"

namespace ts::solar {

// horizons: radians at phi = 2 pi k / size (internal azimuth). Returns [period * kQuantities + q].
std::vector<double> reference_insolation(const InsolationSettings& settings, double latitude_deg, double z_m,
                                         const glm::dvec3& normal, const std::vector<float>& horizons);
// The same with the sun's path given (sample_sun_path of the same settings), for many texels.
std::vector<double> reference_insolation(const InsolationSettings& settings, const std::vector<EphemerisSample>& path,
                                         double latitude_deg, double z_m, const glm::dvec3& normal,
                                         const std::vector<float>& horizons);

}  // namespace ts::solar
