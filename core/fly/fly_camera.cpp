#include "core/fly/fly_camera.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/util/angles.hpp"

namespace ts::fly {

double Projection::vertical_fov_rad() const {
    const double half_h = std::tan(0.5 * radians(horizontal_fov_deg));
    return 2.0 * std::atan(half_h * double(height) / double(width));
}

CameraAxes camera_axes(double heading_deg, double pitch_deg, double roll_deg) {
    const double h = radians(heading_deg), p = radians(pitch_deg), r = radians(roll_deg);
    const glm::dvec3 forward{std::sin(h) * std::cos(p), std::cos(h) * std::cos(p), std::sin(p)};
    const glm::dvec3 right0{std::cos(h), -std::sin(h), 0.0};
    const glm::dvec3 up0 = glm::cross(right0, forward);
    // Roll turns right and up about forward; positive roll lowers the right side.
    const glm::dvec3 right = std::cos(r) * right0 - std::sin(r) * up0;
    const glm::dvec3 up = std::sin(r) * right0 + std::cos(r) * up0;
    return {forward, right, up};
}

glm::dmat4 view_rotation(const CameraPose& pose) {
    const CameraAxes a = camera_axes(pose.heading_deg, pose.pitch_deg, pose.roll_deg);
    glm::dmat4 m(1.0);
    // Rows: camera x = right, y = down, z = forward (glm is column-major: m[col][row]).
    for (int i = 0; i < 3; ++i) {
        m[i][0] = a.right[i];
        m[i][1] = -a.up[i];
        m[i][2] = a.forward[i];
    }
    return m;
}

glm::dmat4 projection_matrix(const Projection& p) {
    const double fx = 1.0 / std::tan(0.5 * radians(p.horizontal_fov_deg));
    const double fy = 1.0 / std::tan(0.5 * p.vertical_fov_rad());
    glm::dmat4 m(0.0);
    m[0][0] = fx;
    m[1][1] = fy;
    m[3][2] = p.near_m;  // clip z = near, clip w = z: depth = near / z
    m[2][3] = 1.0;
    return m;
}

void direction_angles(const glm::dvec3& dir, double& heading_deg, double& pitch_deg) {
    const glm::dvec3 d = glm::normalize(dir);
    heading_deg = degrees(std::atan2(d.x, d.y));
    if (heading_deg < 0) heading_deg += 360.0;
    pitch_deg = degrees(std::asin(std::clamp(d.z, -1.0, 1.0)));
}

}  // namespace ts::fly
