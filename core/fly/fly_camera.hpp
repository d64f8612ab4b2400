#pragma once
// The flythrough camera: a pose (eye in the GridFrame's metres, heading clockwise from north,
// pitch above the horizontal, roll right wing down) and the matrices the GPU draws with.
// Eye-relative: the view matrix has no translation (the vertex shader subtracts the eye in
// float from positions near it), the projection is reversed-Z with an infinite far plane
// (depth = near / distance along the view axis, cleared to 0, test GREATER), so depth keeps
// its precision from a metre to the horizon.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace ts::fly {

struct CameraPose {
    glm::dvec3 eye{0.0};  // east, north, height above the datum (m)
    double heading_deg = 0, pitch_deg = 0, roll_deg = 0;
};

struct Projection {
    double horizontal_fov_deg = 60;
    int width = 960, height = 540;
    double near_m = 1.0;
    double vertical_fov_rad() const;
};

// Unit vectors of the camera in ENU: forward, right, up (after heading, pitch, roll).
struct CameraAxes {
    glm::dvec3 forward, right, up;
};
CameraAxes camera_axes(double heading_deg, double pitch_deg, double roll_deg);

// World (ENU, eye-relative) -> camera (x right, y down, z forward), then clip.
glm::dmat4 view_rotation(const CameraPose& pose);
glm::dmat4 projection_matrix(const Projection& p);
inline glm::dmat4 eye_relative_view_projection(const CameraPose& pose, const Projection& p) {
    return projection_matrix(p) * view_rotation(pose);
}

// Heading (clockwise from north) and pitch of a direction in ENU.
void direction_angles(const glm::dvec3& dir, double& heading_deg, double& pitch_deg);

}  // namespace ts::fly
