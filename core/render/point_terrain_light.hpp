#pragma once
// The light the terrain lets reach one point in the air (the flythrough's aircraft centre):
// the same horizons and log-SH as a mesh vertex (mesh_lighting.hpp, "Terrain -> mesh"), reduced
// to what a shader can use with any normal:
//
//   V_log(p)   = project(horizons of the terrain from p)   (PointHorizons, SliceProjector)
//   L_vis(p)   = exp(V_log) * L_sky                          (SH exp, SH product per channel)
//   sun_vis(p) = the terrain's disc fraction in the sun's azimuth
//
// The shader dots L_vis with the clamped cosine turned to its normal: exp(V_log) * L_sky first
// then the cosine, where mesh_lighting exponentiates V_log + the cosine's log per normal (one
// normal per vertex there, any per fragment here). So an aircraft low in a valley is darker
// and loses the sun behind a ridge.
#include <array>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/light/sky.hpp"
#include "core/sh/exp_method.hpp"
#include "core/terrain/height_grid.hpp"
#include "core/visibility/horizon_sh.hpp"
#include "core/visibility/point_horizons.hpp"

namespace ts::render {

struct PointTerrainLightOptions {
    int directions = 32;  // horizon azimuths (as MeshLightingOptions::directions)
    bool curvature = true;
    float terrain_log_eps = visibility::kDefaultVisibilityLogEps;
    sh::ExpMethod exp_method = sh::ExpMethod::scaling_squaring;
    // As visibility::PointHorizonOptions::base_plane.
    bool base_plane = true;
};

struct PointTerrainLight {
    light::SkySh visible_sky{};  // exp(V_log) * L_sky, the sky's units
    float sun_fraction = 1.0f;   // visible fraction of the sun's disc
};

class PointTerrainLighting {
public:
    // `grid` must outlive this.
    PointTerrainLighting(const terrain::HeightGrid& grid, const PointTerrainLightOptions& options = {});

    // At `texel` (texel-centre coordinates, on or off the grid), z metres above the datum;
    // `sun`: unit ENU towards the disc's centre.
    PointTerrainLight light(glm::dvec2 texel, double z, const light::SkySh& sky_sh, const glm::dvec3& sun,
                            double sun_radius_rad) const;

    // Its parts, to combine grids (a window's near terrain, a coarse copy's far terrain): the
    // options' `directions` horizon angles (radians) into `out`, the sun's visible fraction, and
    // the light from horizons and a sun fraction.
    int directions() const { return options_.directions; }
    void horizons(glm::dvec2 texel, double z, float* out) const;
    double sun_fraction(glm::dvec2 texel, double z, const glm::dvec3& sun, double sun_radius_rad) const;
    PointTerrainLight light_from(const float* horizons, double sun_fraction, const light::SkySh& sky_sh) const;

private:
    PointTerrainLightOptions options_;
    visibility::PointHorizons horizons_;
};

}  // namespace ts::render
