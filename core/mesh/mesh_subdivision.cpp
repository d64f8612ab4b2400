#include "core/mesh/mesh_subdivision.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

namespace ts::mesh {

namespace {
TriangleMesh subdivide_once(const TriangleMesh& in) {
    TriangleMesh out;
    out.materials = in.materials;
    const std::size_t n = in.triangle_count();
    out.positions.reserve(12 * n);
    out.normals.reserve(12 * n);
    out.material.reserve(4 * n);
    for (std::size_t t = 0; t < n; ++t) {
        const glm::vec3* p = &in.positions[3 * t];
        const glm::vec3* nn = &in.normals[3 * t];
        const glm::vec3 mp[3] = {0.5f * (p[0] + p[1]), 0.5f * (p[1] + p[2]), 0.5f * (p[2] + p[0])};
        const glm::vec3 mn[3] = {glm::normalize(nn[0] + nn[1]), glm::normalize(nn[1] + nn[2]),
                                 glm::normalize(nn[2] + nn[0])};
        // Corner triangles, then the middle one; all keep the original winding.
        const glm::vec3 tp[4][3] = {{p[0], mp[0], mp[2]}, {mp[0], p[1], mp[1]}, {mp[2], mp[1], p[2]}, {mp[0], mp[1], mp[2]}};
        const glm::vec3 tn[4][3] = {{nn[0], mn[0], mn[2]}, {mn[0], nn[1], mn[1]}, {mn[2], mn[1], nn[2]}, {mn[0], mn[1], mn[2]}};
        for (int s = 0; s < 4; ++s) {
            for (int k = 0; k < 3; ++k) {
                out.positions.push_back(tp[s][k]);
                // Opposite corner normals sum to zero: keep one of them rather than a NaN.
                out.normals.push_back(glm::any(glm::isnan(tn[s][k])) ? nn[0] : tn[s][k]);
            }
            out.material.push_back(in.material[t]);
        }
    }
    return out;
}
}  // namespace

TriangleMesh subdivide_midpoint(const TriangleMesh& mesh, int levels) {
    TriangleMesh out = mesh;
    for (int i = 0; i < levels; ++i) out = subdivide_once(out);
    return out;
}

}  // namespace ts::mesh
