#pragma once
// Projected SH product and the tripling tensor Gamma_ijk = int y_i y_j y_k dw [Ng, Ramamoorthi,
// Hanrahan 2004; Snyder 2006]. The product c = a * b keeps order 4: c_k = sum_ij Gamma_ijk a_i b_j.
// Gamma is computed once by an exact quadrature (sphere_quadrature.hpp: degree 9 needs 5 x 10
// points; we use 8 x 16) and only non-zeros with i <= j are stored (symmetric in i, j).
#include <cstdint>
#include <vector>

#include "core/sh/sh_basis.hpp"

namespace ts::sh {

struct TripleEntry {
    std::uint8_t i, j, k;  // i <= j
    float value;           // Gamma_ijk
};

// The non-zeros, sorted by k then i then j; built on first use, immutable afterwards.
const std::vector<TripleEntry>& tripling_tensor();
// Gamma_ijk in double (full dense 16^3 table, also built once), for tests and references.
double tripling(int i, int j, int k);

// Hot path (float, no allocation): out = a * b and out = a * a. out may not alias inputs.
void product(const float* a, const float* b, float* out);
void square(const float* a, float* out);

ShVec product(const ShVec& a, const ShVec& b);

}  // namespace ts::sh
