#pragma once
// Midpoint subdivision: each triangle into four, `levels` times (x4 per level), the surface
// unchanged. Makes the large meshes the benchmarks need out of the shared ones.
#include "core/mesh/triangle_mesh.hpp"

namespace ts::mesh {

TriangleMesh subdivide_midpoint(const TriangleMesh& mesh, int levels);

}  // namespace ts::mesh
