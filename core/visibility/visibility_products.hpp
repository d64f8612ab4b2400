#pragma once
// The per-texel products of a HorizonSet in one pass over its D planes: log-SH visibility
// (as log_sh_raster), sky view factor and visible sky fraction with linear wedges (as
// svf_raster / sky_visible_raster with WedgeRule::linear).
//
// Why one pass: reading the D planes once per block of texels and computing the sines and
// cosines from short polynomials (small_angle_trig.hpp) in loops vectorised across texels is
// several times faster than per-texel libm calls and strided plane reads (docs/performance.md).
// Same formulas as the per-texel code (ts_slice_sh_integrals_sc of sh_shared.h, the wedge
// means of sky_shared.h), all in double, rounded to float at the end; the agreement with
// the per-texel libm code is tested (tests/visibility/visibility_products_test.cpp).
#include <vector>

#include "core/util/uninitialised_vector.hpp"
#include "core/visibility/horizon_set.hpp"
#include "core/visibility/horizon_sh.hpp"

namespace ts::visibility {

struct ProductRequest {
    bool log_sh = true;  // needs D >= 4 (InputError otherwise)
    bool svf = true;
    bool sky_visible = true;
    float log_eps = kDefaultVisibilityLogEps;
    int threads = 0;  // 0 = one per core
};

// Layouts as log_sh_raster ([coefficient][texel]), svf_raster and sky_visible_raster; a
// product not requested is left empty. NaN everywhere for void receivers (any NaN horizon).
// The pass writes every texel, so the buffers are not zero-filled first (a single-threaded
// memset of the 92 MB log-SH of a whole SRTM tile, core/util/uninitialised_vector.hpp).
struct VisibilityProducts {
    UninitialisedVector<float> log_sh, svf, sky_visible;
};

VisibilityProducts visibility_products(const HorizonSet& set, const ProductRequest& request = {});

// The same into caller-owned buffers (16 x texels floats for log-SH, texels for the others;
// a buffer whose product is not requested may be null).
struct ProductOutputs {
    float* log_sh = nullptr;
    float* svf = nullptr;
    float* sky_visible = nullptr;
};
void visibility_products_into(const HorizonSet& set, const ProductRequest& request, const ProductOutputs& out);

}  // namespace ts::visibility
