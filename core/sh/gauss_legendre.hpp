#pragma once
// Gauss-Legendre quadrature nodes and weights on [-1, 1] (exact for polynomials of degree
// < 2n). Nodes by Newton iteration on P_n from the Tricomi initial guess [Abramowitz-Stegun
// 25.4.29 and standard practice], converged to machine precision.
#include <vector>

namespace ts::sh {

struct GaussLegendre {
    std::vector<double> nodes;
    std::vector<double> weights;
};

GaussLegendre gauss_legendre(int n);

// The same rule mapped to [a, b].
GaussLegendre gauss_legendre(int n, double a, double b);

}  // namespace ts::sh
