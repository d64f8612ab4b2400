#include "core/mesh/up_axis.hpp"

#include <algorithm>
#include <array>
#include <cctype>

#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"

namespace ts::mesh {

UpAxis parse_up_axis(const std::string& text) {
    std::string t = text;
    std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (t == "auto") return UpAxis::automatic;
    if (t == "x") return UpAxis::x;
    if (t == "y") return UpAxis::y;
    if (t == "z") return UpAxis::z;
    throw QuantityError(Quantity::up_axis, "'" + text + "'", "not one of auto, x, y, z");
}

UpAxis default_up_axis(const std::string& extension) {
    std::string e = extension;
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    static constexpr std::array<const char*, 3> kZUp = {".stl", ".ply", ".off"};
    for (const char* z : kZUp)
        if (e == z) return UpAxis::z;
    return UpAxis::y;
}

glm::dmat3 to_z_up(UpAxis up, int up_sign) {
    // glm is column-major: dmat3(c0, c1, c2) has columns c0, c1, c2 = images of x, y, z.
    glm::dmat3 r(1.0);
    switch (up) {
    case UpAxis::x:  // cyclic (x, y, z) -> (z, x, y): x up, y east, z north
        r = glm::dmat3(glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0));
        break;
    case UpAxis::y:  // +90 deg about x: (x, y, z) -> (x, -z, y)
    case UpAxis::automatic:
        r = glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, -1, 0));
        break;
    case UpAxis::z:
        break;
    }
    // Up pointing down the axis: a half turn about the new x keeps the frame right-handed.
    if (up_sign < 0) r = glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, -1)) * r;
    return r;
}

}  // namespace ts::mesh
