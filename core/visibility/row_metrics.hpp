#pragma once
// Per-row ground spacing of a height grid, with what the horizon searches need to follow a
// line of constant azimuth (a rhumb line) on a grid whose east-west spacing varies by row.
//
// With rho(r) = dy(r) / dx(r) and G(r) = integral_0^r rho, a constant-azimuth line satisfies
// col * sin(phi) + G(row) * cos(phi) = const: in (col, G) coordinates it is straight. On a
// projected grid G is linear and the lines are the usual straight grid lines.
#include <cstddef>
#include <vector>

#include "core/terrain/height_grid.hpp"

namespace ts::visibility {

class RowMetrics {
public:
    explicit RowMetrics(const terrain::HeightGrid& grid);

    int rows() const { return int(dx_.size()); }
    // Spacing in metres at a fractional row (linear between rows, clamped at the ends).
    double dx_at(double row) const { return lerp_rows(dx_, row); }
    double dy_at(double row) const { return lerp_rows(dy_, row); }
    double dx(int row) const { return dx_[std::size_t(row)]; }
    double dy(int row) const { return dy_[std::size_t(row)]; }

    // G at integer rows (trapezoid rule on rho) and its piecewise-linear inverse.
    double g(int row) const { return g_[std::size_t(row)]; }
    double g_max() const { return g_.back(); }
    double mean_rho() const { return mean_rho_; }
    double min_rho() const { return min_rho_; }
    double rho(double row) const { return dy_at(row) / dx_at(row); }
    // East-west spacing is floored at this fraction of the north-south one (pole rows).
    static constexpr double kMinAspect = 0.01;
    // Fractional row with G(row) = value; value must lie in [0, g_max()].
    double row_of_g(double value) const;
    // The same, searching from row `hint` and leaving the row found there: a sweep line's
    // consecutive samples are a row or less apart. The result does not depend on the hint.
    double row_of_g(double value, int& hint) const {
        const int last = int(g_.size()) - 1;
        if (last == 0 || value <= 0) return 0.0;
        if (value >= g_.back()) return double(last);
        return row_in_bracket(value, hint = bracket(value, hint));
    }

private:
    // The row r with g(r) <= value <= g(r + 1), for value inside (0, g_max()), searched from
    // `start`; where value is a knot either neighbouring bracket gives the same row_in_bracket.
    int bracket(double value, int start) const {
        const int last = int(g_.size()) - 1;
        int r = start < 0 ? 0 : (start > last - 1 ? last - 1 : start);
        while (r < last - 1 && g_[std::size_t(r) + 1] < value) ++r;
        while (r > 0 && g_[std::size_t(r)] > value) --r;
        return r;
    }
    double row_in_bracket(double value, int r) const {
        const double g0 = g_[std::size_t(r)], g1 = g_[std::size_t(r) + 1];
        return double(r) + (value - g0) / (g1 - g0);
    }
    // Inline: the sweep calls it for every line sample.
    static double lerp_rows(const std::vector<double>& v, double row) {
        if (row <= 0) return v.front();
        const double last = double(v.size() - 1);
        if (row >= last) return v.back();
        const auto r0 = std::size_t(row);
        const double f = row - double(r0);
        return v[r0] + f * (v[r0 + 1] - v[r0]);
    }
    std::vector<double> dx_, dy_, g_;
    double mean_rho_ = 1.0, min_rho_ = 1.0;
};

}  // namespace ts::visibility
