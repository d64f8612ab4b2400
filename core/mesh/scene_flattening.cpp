#include "core/mesh/scene_flattening.hpp"

#include <cmath>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/util/error.hpp"

namespace ts::mesh {
namespace {

bool finite(const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

void append_mesh(const ImportedMesh& me, const glm::dmat4& m, const glm::dmat3& normal_m, const std::string& shown,
                 TriangleMesh& out) {
    const std::size_t nv = me.vertices.size();
    for (std::size_t t = 0; t + 2 < me.triangles.size(); t += 3) {
        const std::uint32_t idx[3] = {me.triangles[t], me.triangles[t + 1], me.triangles[t + 2]};
        for (std::uint32_t i : idx)
            if (i >= nv) throw input_error(shown, "a triangle refers to a vertex the mesh does not have");
        glm::vec3 p[3];
        for (int k = 0; k < 3; ++k) p[k] = glm::vec3(m * glm::dvec4(glm::dvec3(me.vertices[idx[k]]), 1.0));
        if (!finite(p[0]) || !finite(p[1]) || !finite(p[2])) continue;
        glm::dvec3 face_n = glm::cross(glm::dvec3(p[1] - p[0]), glm::dvec3(p[2] - p[0]));
        const double len = glm::length(face_n);
        face_n = len > 0 && std::isfinite(len) ? face_n / len : glm::dvec3(0, 0, 1);
        for (int k = 0; k < 3; ++k) {
            glm::dvec3 nk = face_n;
            if (!me.normals.empty()) {
                const glm::dvec3 t3 = normal_m * glm::dvec3(me.normals[idx[k]]);
                const double tl = glm::length(t3);
                if (tl > 0 && std::isfinite(tl)) nk = t3 / tl;
            }
            out.positions.push_back(p[k]);
            out.normals.push_back(glm::vec3(nk));
        }
        out.material.push_back(me.material);
    }
}

}  // namespace

TriangleMesh flatten_scene(const ImportedScene& scene, const glm::dmat4& root, const std::string& shown) {
    TriangleMesh out;
    if (scene.nodes.empty()) throw input_error(shown, "no triangles (no mesh in the file)");
    std::vector<bool> seen(scene.nodes.size(), false);
    // Depth first with an explicit stack: a node tree may be deeper than the call stack allows.
    std::vector<std::pair<std::uint32_t, glm::dmat4>> stack{{0u, root}};
    while (!stack.empty()) {
        auto [index, parent] = stack.back();
        stack.pop_back();
        if (seen[index]) throw input_error(shown, "the node tree is not a tree (a node is reached twice)");
        seen[index] = true;
        const ImportedNode& n = scene.nodes[index];
        const glm::dmat4 m = parent * n.transform;
        const glm::dmat3 normal_m = glm::transpose(glm::inverse(glm::dmat3(m)));
        for (std::uint32_t mi : n.meshes) {
            if (mi >= scene.meshes.size()) throw input_error(shown, "a node refers to a mesh the file does not have");
            append_mesh(scene.meshes[mi], m, normal_m, shown, out);
        }
        // Children pushed last to first, so they are walked in file order.
        for (auto c = n.children.rbegin(); c != n.children.rend(); ++c) {
            if (*c >= scene.nodes.size()) throw input_error(shown, "a node refers to a child the file does not have");
            stack.emplace_back(*c, m);
        }
    }
    if (out.triangle_count() == 0) throw input_error(shown, "no triangles");
    out.materials = scene.materials;
    if (out.materials.empty()) out.materials.push_back(MeshMaterial{"default"});
    for (std::uint32_t& mat : out.material)
        if (mat >= out.materials.size()) mat = 0;
    return out;
}

}  // namespace ts::mesh
