#pragma once
// Where the flythrough's camera is: chase (behind and above the aircraft, looking at it),
// cockpit (the aircraft's own pose), free flight (moved by keys and the mouse) or orbit
// (around a point, turned by the mouse). Pure pose math; the keys are the app's.
#include <glm/vec3.hpp>

#include "core/fly/fly_camera.hpp"

namespace ts::fly {

enum class CameraMode { chase, cockpit, free, orbit };
const char* camera_mode_name(CameraMode mode);

struct ChaseOffsets {
    double back_m = 60.0;  // behind the aircraft along its heading
    double up_m = 15.0;    // above it
};
CameraPose chase_pose(const CameraPose& aircraft, const ChaseOffsets& offsets = {});

// Free flight: move along the view (forward), sideways (right) and up, in metres per second
// times the speed; turn by degrees.
struct FreeFlight {
    CameraPose pose;
    double speed_mps = 150.0;
    void move(double forward, double right, double up, double dt_s);
    void turn(double d_heading_deg, double d_pitch_deg);
};

struct Orbit {
    glm::dvec3 centre{0.0};
    double distance_m = 3000.0, heading_deg = 0.0, pitch_deg = -30.0;
    CameraPose pose() const;  // looking at the centre from `distance_m` away
    void turn(double d_heading_deg, double d_pitch_deg);
    void zoom(double factor);
};

}  // namespace ts::fly
