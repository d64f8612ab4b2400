#pragma once
// Rotation of a whole SH vector. Each band l rotates by itself with a (2l+1)x(2l+1) matrix
// M_l(R) satisfying y_l(R d) = M_l y_l(d) for every direction d. M_l is found from 2l+1 fixed
// directions d_k: M_l = Y_l(R d_k) * Y_l(d_k)^-1 (the inverses are precomputed once), so
// building a rotation costs 15 basis evaluations and three small matrix products.
#include <array>
#include <glm/mat3x3.hpp>

#include "core/sh/sh_basis.hpp"

namespace ts::sh {

class ShRotation {
public:
    // The rotation that moves direction d to R d: apply(f) is the projection of
    // g(w) = f(R^T w), i.e. every feature of f turned by R.
    explicit ShRotation(const glm::dmat3& R);

    // Lighting given in world coordinates, expressed in a local frame whose axes (tangent,
    // bitangent, normal) are the columns of `frame` (orthonormal, right-handed): the local
    // function is g(w_local) = f(frame * w_local).
    static ShRotation to_local_frame(const glm::dmat3& frame);

    ShVec apply(const ShVec& f) const;
    void apply(const float in[kCount], float out[kCount]) const;

private:
    std::array<double, 9> m1_{};
    std::array<double, 25> m2_{};
    std::array<double, 49> m3_{};
};

}  // namespace ts::sh
