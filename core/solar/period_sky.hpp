#pragma once
// A period's diffuse sky, summed once (docs/insolation.md, "Diffuse"): the sky's radiance is
// linear in what each time step adds, so the period's sky is the sum of every step's sky, and a
// texel's diffuse irradiation is one lookup per azimuth sector against that sum, whatever the
// number of steps. Each step adds the CIE clear sky's shape (cie_clear_sky.hpp) for its sun,
// scaled to ESRA's diffuse horizontal irradiance times the step's length.
//
// Stored per azimuth sector and horizon elevation: the vector sum of L(w) w dOmega over the
// sector's sky above that elevation (Wh/m^2 per unit cosine, ENU), so that a texel with normal n
// and horizon h in the sector receives n . C(sector, h); the receiver's own plane is its caller's
// clamp of h, as for the sun (InsolationModel::run).
#include <cstddef>
#include <vector>

namespace ts::solar {

struct SkyGrid {
    int sectors = 64;                            // sector s centred on phi = 2 pi s / sectors
    double first_rad = -0.523598775598298873;    // -30 degrees: lower horizons see all the sky
    double step_rad = 0.0174532925199432958;     // 1-degree cells; linear within a cell
    int cells = 120;                             // up to the zenith
};

// The sky's shape integrated over each cell of the grid for every sun elevation (1-degree steps
// 0..90) and every offset between the sun's sector and a sky sector, in the sector's own frame
// (towards its centre, across it, up), normalised so that the whole sky above the horizontal
// gives a horizontal plane 1. Built once per job (~0.1 s).
class SkyKernel {
public:
    static constexpr int kSunElevations = 91;
    SkyKernel(SkyGrid grid, int threads);
    const SkyGrid& grid() const { return grid_; }
    // grid.cells x 3 floats for sun elevation bin eb (degrees) and offset o = sector - sun sector.
    const float* cells(int eb, int offset) const {
        return values_.data() + (std::size_t(eb) * std::size_t(grid_.sectors) + std::size_t(offset)) * std::size_t(grid_.cells) * 3;
    }

private:
    SkyGrid grid_;
    std::vector<float> values_;
};

class PeriodSky {
public:
    explicit PeriodSky(const SkyGrid& grid);
    // One time step: the sun's elevation (radians; below 0: nothing) and azimuth phi (radians,
    // counter-clockwise from east, as the tables' bins), and ESRA's diffuse horizontal
    // irradiation of the step (Wh/m^2), spread linearly over the kernel's neighbouring sun
    // elevations and sectors.
    void add_sun(double elevation_rad, double phi_rad, double horizontal_wh);
    // The sum over the steps, as cumulative tables; add_sun may not follow.
    void finish(const SkyKernel& kernel);
    // acc[0..2] += w * C(sector, horizon): the sky of the sector above the horizon.
    void add_visible(int sector, float horizon_rad, float w, float* acc) const {
        const float x = (horizon_rad - first_) * inv_step_;
        const float* a = cumulative_.data() + std::size_t(sector) * row_;
        if (x <= 0) {
            for (int c = 0; c < 3; ++c) acc[c] += w * a[c];
            return;
        }
        if (x >= float(cells_)) return;
        const int k = int(x);
        const float f = x - float(k);
        a += std::size_t(k) * 4;
        for (int c = 0; c < 3; ++c) acc[c] += w * ((1 - f) * a[c] + f * a[4 + c]);
    }
    // Sum of add_sun's horizontal irradiation (what an open horizontal plane receives).
    double horizontal_wh() const { return horizontal_wh_; }
    std::size_t bytes() const { return cumulative_.size() * sizeof(float); }

private:
    SkyGrid grid_;
    std::vector<double> sun_weight_;  // [sun elevation bin][sector], until finish()
    std::vector<float> cumulative_;   // [sector][cells + 1][4]: from elevation cell k to the zenith
    std::size_t row_ = 0;
    int cells_ = 0;
    float first_ = 0, inv_step_ = 1;
    double horizontal_wh_ = 0;
};

}  // namespace ts::solar
