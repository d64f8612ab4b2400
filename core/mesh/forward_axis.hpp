#pragma once
// Which axis of an imported mesh (normalised frame: Z up, metres) is its nose, the direction a
// heading points. One convention for every command (render, relight, fly):
//   - FlightGear's AC3D aircraft (Y up in the file, the nose towards -X): -x after import;
//   - glTF 2.0 (the spec: +Y up, the asset's front towards +Z): the Y-up file turned Z-up maps
//     +Z to -Y, so -y after import;
//   - any other format: -x, as FlightGear's models (the common case for flight-sim users).
// The placement turns this axis onto the model's +y before heading, pitch and roll
// (core/mesh/placement.hpp), so heading 90 puts the nose east whatever the format.
#include <string>
#include <string_view>

namespace ts::mesh {

enum class ForwardAxis { plus_x, minus_x, plus_y, minus_y };

// "+x", "-x", "+y", "-y"; nullopt-like: throws ts::QuantityError (Quantity::mesh_forward) otherwise.
ForwardAxis parse_forward_axis(std::string_view text);
std::string_view forward_axis_name(ForwardAxis axis);
// The default for a mesh file by its extension: -y for .gltf/.glb, -x for every other format.
ForwardAxis default_forward_axis(const std::string& extension);
// The yaw (degrees, counter-clockwise about up) that turns `axis` onto +y.
double forward_yaw_deg(ForwardAxis axis);

}  // namespace ts::mesh
