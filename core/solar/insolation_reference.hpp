#pragma once
// The brute-force reference of InsolationModel::texel: the same model summed time step by time
// step, with the sun's visibility computed at each step from the horizon in the sun's own
// azimuth (linear between `horizons.size()` evenly spaced azimuths, given as finely as a test
// wants) and the ESRA terms at the texel's own height; the diffuse sky integrated over the
// visible sky at each step (ReferenceSky). Slow on purpose; for tests and studies.
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/solar/insolation_model.hpp"

namespace ts::solar {

// The diffuse sky by quadrature: at every step (or the middle step of every `stride` steps, its
// share weighted by each step's own ESRA diffuse), the CIE clear sky's radiance integrated over
// the sky the texel sees above its horizons, at `azimuths` azimuths (0: the horizons' own) and
// `elevations` midpoints from each azimuth's horizon to the zenith, normalised by the same sky
// over the horizontal plane's hemisphere.
struct ReferenceSky {
    int stride = 1;
    int azimuths = 0;
    int elevations = 48;
};

// horizons: radians at phi = 2 pi k / size (internal azimuth). Returns [period * kQuantities + q].
std::vector<double> reference_insolation(const InsolationSettings& settings, double latitude_deg, double z_m,
                                         const glm::dvec3& normal, const std::vector<float>& horizons,
                                         const ReferenceSky& sky = {});
// The same with the sun's path given (sample_sun_path of the same settings), for many texels.
std::vector<double> reference_insolation(const InsolationSettings& settings, const std::vector<EphemerisSample>& path,
                                         double latitude_deg, double z_m, const glm::dvec3& normal,
                                         const std::vector<float>& horizons, const ReferenceSky& sky = {});

}  // namespace ts::solar
