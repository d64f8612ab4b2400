#pragma once
// The diffuse transfer of a height-field texel projected exactly from its horizons
// (docs/rendering.md, "The terrain's transfer"):
//
//   T_i = 1/pi  int_phi  int_{e0(phi)}^{pi/2}  (n . w) Y_i(w) cos e  de dphi,
//   e0(phi) = max(horizon(phi), the texel's own plane at phi),  w = (cos e cos phi, cos e sin phi, sin e)
//
// what the log-SH path (exp of the log-visibility plus the log-cosine lobe) approximates. That
// path's log floor below the horizon (log 0.1) lets a share of the blocked sky through: under an
// overcast sky a valley came out too bright by about 0.27 (1 - sky view factor) against Blender
// Cycles, which no band correction removes. The terrain's own transfer is therefore projected
// here; the log-SH product stays what combines it with mesh blockers (shading_state.cpp).
//
// At a fixed azimuth, (n . w) Y_i(w) cos e is a trigonometric polynomial in e of degree l + 2, so
// its integral from e0 up is a fixed combination of e0, sin(m e0) and cos(m e0), m <= l + 2:
// made once per azimuth and coefficient (a 16-point DFT), then a dot product per texel. The
// azimuth integral is the trapezoid rule over the D horizon azimuths, exact for a level or
// tilted plane (a smooth periodic integrand) and second order where a horizon crosses the plane.
#include <cstddef>

#include "core/terrain/terrain_normals.hpp"
#include "core/visibility/horizon_set.hpp"

namespace ts::render {

struct HorizonTransferInputs {
    const visibility::HorizonSet* horizons = nullptr;  // D >= 4 azimuths; NaN: void texel
    const NormalField* normals = nullptr;              // the same texels (unit, z > 0)
    int coefficients = 9;                              // 9 (bands 0..2) or 16; the rest are written 0
    int threads = 0;
};

// Writes T [16][texels] (band-sequential; NaN for void texels). Throws std::invalid_argument
// when the inputs do not match.
void horizon_transfer(const HorizonTransferInputs& in, float* transfer_out);

}  // namespace ts::render
