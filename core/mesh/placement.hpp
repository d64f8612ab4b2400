#pragma once
// Where a mesh stands in the world: lon/lat, a height, an attitude in the local ENU frame and a
// scale. The normalised model frame (Z up, metres) is turned into ENU by heading, pitch, roll
// in the aerospace order: at heading = pitch = roll = 0 model +x points east, +y north, +z up;
// heading turns the model's +y (its "forward") clockwise from north about up, pitch lifts +y
// (nose up) about the model's +x, roll lowers the model's +x ("right wing down") about +y.
// Before all three, forward_yaw_deg turns the mesh's nose onto +y (core/mesh/forward_axis.hpp):
// 0 for a mesh whose nose is +y, -90 for FlightGear's AC3D aircraft (nose -x).
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

namespace ts::geo {
class LocalFrame;
}

namespace ts::mesh {

struct Placement {
    double lon_deg = 0.0;
    double lat_deg = 0.0;
    double height_m = 0.0;             // above the DEM's datum, or above the ground when above_ground
    bool above_ground = false;         // "agl": height_m is added to the terrain height under the origin
    double heading_deg = 0.0;          // clockwise from north
    double pitch_deg = 0.0;            // nose up
    double roll_deg = 0.0;             // right side down
    double scale = 1.0;                // uniform, > 0
    double forward_yaw_deg = 0.0;      // counter-clockwise about up, turning the nose onto +y first
};

// Throws ts::InputError for a latitude outside [-90, 90], a longitude outside [-180, 360], a
// non-finite number or a scale <= 0.
void validate(const Placement& placement);

// The attitude alone: R = Rz(-heading) * Rx(pitch) * Ry(roll) * Rz(forward_yaw).
glm::dmat3 placement_rotation(const Placement& placement);

// model (normalised frame, metres) -> ENU metres of `frame`. ground_height_m is the terrain's
// height under the placement (same datum as frame's origin), used only when above_ground.
glm::dmat4 model_to_enu(const Placement& placement, const geo::LocalFrame& frame, double ground_height_m = 0.0);

}  // namespace ts::mesh
