#include "core/quality/visibility_quality.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"

namespace ts::quality {

double mean_tan_slope(const terrain::HeightGrid& g, int col0, int row0, int width, int height) {
    const int w = width < 0 ? g.width - col0 : width, h = height < 0 ? g.height - row0 : height;
    double sum = 0;
    long n = 0;
    for (int r = row0; r < row0 + h; ++r)
        for (int c = col0; c < col0 + w; ++c) {
            const int cl = std::max(c - 1, 0), cr = std::min(c + 1, g.width - 1);
            const int ru = std::max(r - 1, 0), rd = std::min(r + 1, g.height - 1);
            if (cl == cr && ru == rd) continue;
            const double dx = cr > cl ? (g.at(cr, r) - g.at(cl, r)) / ((cr - cl) * g.dx_m[std::size_t(r)]) : 0.0;
            const double dy = rd > ru ? (g.at(c, ru) - g.at(c, rd)) / ((rd - ru) * g.dy_m[std::size_t(r)]) : 0.0;
            const double t = std::hypot(dx, dy);
            if (!std::isfinite(t)) continue;  // a void in the stencil
            sum += t;
            ++n;
        }
    return n ? sum / double(n) : 0.0;
}

const std::vector<VisibilitySetting>& visibility_settings() {
    static const std::vector<VisibilitySetting> table = {
#include "core/quality/visibility_error_table.inc"
    };
    return table;
}

VisibilityChoice choose_visibility(double max_error, double roughness) {
    if (!(max_error > 0)) throw QuantityError(Quantity::max_error, "", "must be > 0 (an svf RMSE, e.g. 0.001)");
    const auto& table = visibility_settings();
    VisibilityChoice choice;
    choice.roughness = roughness;
    choice.met = false;
    choice.setting = table.back();
    for (const VisibilitySetting& s : table)
        if (s.error_per_roughness * roughness <= max_error) {
            choice.setting = s;
            choice.met = true;
            break;
        }
    choice.predicted_error = choice.setting.error_per_roughness * roughness;
    char line[256];
    std::snprintf(line, sizeof line,
                  "%g: %d directions, near field %g texels (predicted svf RMSE %.2g for mean slope "
                  "%.2g = %.1f degrees%s)",
                  max_error, choice.setting.directions, choice.setting.near_field_texels, choice.predicted_error,
                  roughness, std::atan(roughness) * 180.0 / 3.14159265358979323846,
                  choice.met ? "; the cheapest setting under the bound" : "; no setting is predicted under it: the finest");
    choice.reason = line;
    return choice;
}

}  // namespace ts::quality
