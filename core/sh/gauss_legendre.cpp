#include "core/sh/gauss_legendre.hpp"

#include <cmath>
#include <stdexcept>

#include "core/util/angles.hpp"

namespace ts::sh {

GaussLegendre gauss_legendre(int n) {
    if (n < 1) throw std::invalid_argument("gauss_legendre: n must be >= 1");
    GaussLegendre rule;
    rule.nodes.resize(n);
    rule.weights.resize(n);
    for (int i = 0; i < (n + 1) / 2; ++i) {
        double x = std::cos(kPi * (i + 0.75) / (n + 0.5));
        double dp = 0.0;
        for (int iter = 0; iter < 100; ++iter) {
            // P_n(x) and P_n'(x) by the three-term recurrence.
            double p0 = 1.0, p1 = x;
            for (int k = 2; k <= n; ++k) {
                double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            double pn = n == 1 ? x : p1;
            double pn1 = n == 1 ? 1.0 : p0;
            dp = n * (x * pn - pn1) / (x * x - 1.0);
            double dx = pn / dp;
            x -= dx;
            if (std::abs(dx) < 1e-16) break;
        }
        double w = 2.0 / ((1.0 - x * x) * dp * dp);
        rule.nodes[i] = -x;
        rule.nodes[n - 1 - i] = x;
        rule.weights[i] = w;
        rule.weights[n - 1 - i] = w;
    }
    if (n % 2 == 1) rule.nodes[n / 2] = 0.0;
    return rule;
}

GaussLegendre gauss_legendre(int n, double a, double b) {
    GaussLegendre rule = gauss_legendre(n);
    for (int i = 0; i < n; ++i) {
        rule.nodes[i] = 0.5 * (b - a) * rule.nodes[i] + 0.5 * (a + b);
        rule.weights[i] *= 0.5 * (b - a);
    }
    return rule;
}

}  // namespace ts::sh
