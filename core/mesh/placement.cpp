#include "core/mesh/placement.hpp"

#include <cmath>

#include "core/geo/local_frame.hpp"
#include "core/util/angles.hpp"
#include "core/util/error.hpp"

namespace ts::mesh {

void validate(const Placement& p) {
    const double all[] = {p.lon_deg, p.lat_deg, p.height_m, p.heading_deg, p.pitch_deg, p.roll_deg, p.scale, p.forward_yaw_deg};
    for (double v : all)
        if (!std::isfinite(v)) throw InputError("mesh placement: every number must be finite");
    if (p.lat_deg < -90.0 || p.lat_deg > 90.0) throw InputError("mesh placement: latitude must be in [-90, 90]");
    if (p.lon_deg < -180.0 || p.lon_deg > 360.0) throw InputError("mesh placement: longitude must be in [-180, 360]");
    if (!(p.scale > 0.0)) throw InputError("mesh placement: scale must be > 0");
}

glm::dmat3 placement_rotation(const Placement& p) {
    const double h = -radians(p.heading_deg), t = radians(p.pitch_deg), r = radians(p.roll_deg);
    // Columns are the images of x, y, z (glm is column-major).
    const glm::dmat3 rz(glm::dvec3(std::cos(h), std::sin(h), 0), glm::dvec3(-std::sin(h), std::cos(h), 0),
                        glm::dvec3(0, 0, 1));
    const glm::dmat3 rx(glm::dvec3(1, 0, 0), glm::dvec3(0, std::cos(t), std::sin(t)),
                        glm::dvec3(0, -std::sin(t), std::cos(t)));
    const glm::dmat3 ry(glm::dvec3(std::cos(r), 0, -std::sin(r)), glm::dvec3(0, 1, 0),
                        glm::dvec3(std::sin(r), 0, std::cos(r)));
    const double f = radians(p.forward_yaw_deg);
    const glm::dmat3 forward(glm::dvec3(std::cos(f), std::sin(f), 0), glm::dvec3(-std::sin(f), std::cos(f), 0),
                             glm::dvec3(0, 0, 1));
    return rz * rx * ry * forward;
}

glm::dmat4 model_to_enu(const Placement& p, const geo::LocalFrame& frame, double ground_height_m) {
    validate(p);
    const double h = p.height_m + (p.above_ground ? ground_height_m : 0.0);
    const glm::dvec3 origin = frame.to_enu(glm::dvec3(p.lon_deg, p.lat_deg, h));
    glm::dmat4 m(placement_rotation(p) * p.scale);
    m[3] = glm::dvec4(origin, 1.0);
    return m;
}

}  // namespace ts::mesh
