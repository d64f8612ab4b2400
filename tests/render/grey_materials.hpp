#pragma once
// For tests: the rule materials of a grid made one grey Lambert surface (no specular, no
// water), whose shading has closed forms.
#include <algorithm>

#include "core/material/material.hpp"
#include "core/terrain/terrain_normals.hpp"

namespace ts::render::testing {

inline MaterialRaster grey_materials(const terrain::HeightGrid& grid, float albedo) {
    MaterialRaster m = rule_materials(grid, terrain_normals(grid));
    std::fill(m.albedo_r.begin(), m.albedo_r.end(), albedo);
    std::fill(m.albedo_g.begin(), m.albedo_g.end(), albedo);
    std::fill(m.albedo_b.begin(), m.albedo_b.end(), albedo);
    std::fill(m.ks.begin(), m.ks.end(), 0.0f);
    std::fill(m.water.begin(), m.water.end(), 0);
    return m;
}

}  // namespace ts::render::testing
