#include "core/fly/camera_rig.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/util/angles.hpp"

namespace ts::fly {

const char* camera_mode_name(CameraMode mode) {
    switch (mode) {
        case CameraMode::chase: return "chase";
        case CameraMode::cockpit: return "cockpit";
        case CameraMode::free: return "free";
        case CameraMode::orbit: return "orbit";
    }
    return "?";
}

CameraPose chase_pose(const CameraPose& aircraft, const ChaseOffsets& o) {
    const double h = radians(aircraft.heading_deg);
    const glm::dvec3 back{-std::sin(h), -std::cos(h), 0.0};
    CameraPose c;
    c.eye = aircraft.eye + back * o.back_m + glm::dvec3(0, 0, o.up_m);
    direction_angles(aircraft.eye - c.eye, c.heading_deg, c.pitch_deg);
    return c;
}

void FreeFlight::move(double forward, double right, double up, double dt_s) {
    const CameraAxes a = camera_axes(pose.heading_deg, pose.pitch_deg, 0.0);
    pose.eye += (a.forward * forward + a.right * right + glm::dvec3(0, 0, 1) * up) * (speed_mps * dt_s);
}

void FreeFlight::turn(double dh, double dp) {
    pose.heading_deg = std::fmod(pose.heading_deg + dh + 360.0, 360.0);
    pose.pitch_deg = std::clamp(pose.pitch_deg + dp, -89.0, 89.0);
}

CameraPose Orbit::pose() const {
    const CameraAxes a = camera_axes(heading_deg, pitch_deg, 0.0);
    CameraPose c;
    c.eye = centre - a.forward * distance_m;
    c.heading_deg = heading_deg;
    c.pitch_deg = pitch_deg;
    return c;
}

void Orbit::turn(double dh, double dp) {
    heading_deg = std::fmod(heading_deg + dh + 360.0, 360.0);
    pitch_deg = std::clamp(pitch_deg + dp, -89.0, -2.0);
}

void Orbit::zoom(double factor) { distance_m = std::clamp(distance_m * factor, 50.0, 500000.0); }

}  // namespace ts::fly
