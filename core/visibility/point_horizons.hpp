#pragma once
// Horizons seen from any point over a height grid, not only from its texel centres: what the
// terrain hides of the sky and the sun from a mesh's vertices (an aircraft low in a valley, a
// truck on its floor; docs/blockers.md, "Terrain -> mesh").
//
// From the point (texel-centre coordinates, a height above the DEM's datum) a line of constant
// azimuth is marched over the bilinear surface in steps of step_texels (as the texels' reference
// march, bilinear_march.hpp), keeping the highest curvature-corrected slope. Beyond the grid's
// edge the terrain goes on as an infinite plane at the grid's base (its lowest border height),
// whose highest slope is taken in closed form: without it a point in the air would see through
// the ground wherever the DEM ends, with it the horizon of a point h above the plane dips by
// atan(2 sqrt(h c)) (c the curvature factor), the geometric dip. A point off the grid sees the
// plane around it and the DEM beyond. A point below the surface sees a horizon near the zenith
// in most directions (it is dark), without any special case.
#include <limits>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/terrain/height_grid.hpp"
#include "core/visibility/row_metrics.hpp"

namespace ts::visibility {

struct PointHorizonOptions {
    bool curvature = true;     // Earth curvature with refraction (earth_curvature.hpp)
    double step_texels = 0.25; // march step over the grid, texels of the shorter spacing
    // Beyond the grid the base plane (its border's height) stands in for the terrain; false: no
    // terrain there (a window of a larger terrain whose far part another grid gives).
    bool base_plane = true;
};

class PointHorizons {
public:
    // `grid` must outlive this.
    explicit PointHorizons(const terrain::HeightGrid& grid, const PointHorizonOptions& options = {});

    // Highest tan(elevation) of the terrain (grid and base plane) seen from `texel` (col, row:
    // texel-centre coordinates, any value, on or off the grid) at height z (metres above the
    // datum) towards the internal azimuth (cs, sn) = (cos phi, sin phi), phi counter-clockwise
    // from east. band_lo/band_hi as march_max_slope: the answer only needs to be on the right
    // side of the band (the sun's disc).
    double max_slope(glm::dvec2 texel, double z, double cs, double sn,
                     double band_lo = -std::numeric_limits<double>::infinity(),
                     double band_hi = std::numeric_limits<double>::infinity()) const;
    // Elevation angles (radians) of the D horizons at internal azimuths 2 pi d / D into out[D].
    void horizons(glm::dvec2 texel, double z, int directions, float* out) const;
    // Visible fraction of the sun's disc (unit ENU direction towards its centre, angular radius
    // sun_radius_rad) above the horizon in its azimuth.
    double sun_fraction(glm::dvec2 texel, double z, const glm::dvec3& sun, double sun_radius_rad) const;

    double base_height() const { return base_; }
    double curvature() const { return curvature_; }

private:
    // Highest slope of the base plane over horizontal distances [a, b] from a point at z.
    double plane_max_slope(double z, double a, double b) const;

    const terrain::HeightGrid& grid_;
    PointHorizonOptions options_;
    RowMetrics metrics_;
    double curvature_ = 0;
    double base_ = 0;
    float top_ = 0;
};

}  // namespace ts::visibility
