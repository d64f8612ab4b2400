#include "core/mesh/forward_axis.hpp"

#include <algorithm>
#include <cctype>

#include "core/util/quantity_error.hpp"

namespace ts::mesh {

ForwardAxis parse_forward_axis(std::string_view text) {
    for (ForwardAxis a : {ForwardAxis::plus_x, ForwardAxis::minus_x, ForwardAxis::plus_y, ForwardAxis::minus_y})
        if (text == forward_axis_name(a)) return a;
    throw QuantityError(Quantity::mesh_forward, std::string(text), "give auto, +x, -x, +y or -y");
}

std::string_view forward_axis_name(ForwardAxis a) {
    switch (a) {
        case ForwardAxis::plus_x: return "+x";
        case ForwardAxis::minus_x: return "-x";
        case ForwardAxis::plus_y: return "+y";
        case ForwardAxis::minus_y: return "-y";
    }
    return "?";
}

ForwardAxis default_forward_axis(const std::string& extension) {
    std::string e = extension;
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return e == ".gltf" || e == ".glb" ? ForwardAxis::minus_y : ForwardAxis::minus_x;
}

double forward_yaw_deg(ForwardAxis a) {
    switch (a) {
        case ForwardAxis::plus_y: return 0.0;
        case ForwardAxis::minus_x: return -90.0;
        case ForwardAxis::plus_x: return 90.0;
        case ForwardAxis::minus_y: return 180.0;
    }
    return 0.0;
}

}  // namespace ts::mesh
