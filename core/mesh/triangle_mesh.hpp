#pragma once
// A triangle soup in the normalised model frame: Z up, metres, right-handed. Triangles are kept
// apart (three corners each, no shared vertex list) because every consumer here (voxelisation,
// sampling, the preview) walks triangles, and real assets are soups anyway.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace ts::mesh {

struct MeshMaterial {
    std::string name;
    // Linear RGBA base colour: glTF 2 base colour factor, else the diffuse colour. A material
    // whose colour comes from a texture alone reads white (the texture's factor).
    glm::vec4 base_color{0.8f, 0.8f, 0.8f, 1.0f};
    std::string base_color_texture;  // as written in the file (relative to it); may be empty
};

struct TriangleMesh {
    std::vector<glm::vec3> positions;       // 3 per triangle, metres
    std::vector<glm::vec3> normals;         // 3 per triangle, unit (face normal where the file has none)
    std::vector<std::uint32_t> material;    // 1 per triangle, index into materials
    std::vector<MeshMaterial> materials;    // at least one

    std::size_t triangle_count() const { return material.size(); }
};

struct Bounds {
    glm::dvec3 lo{0.0}, hi{0.0};
    glm::dvec3 size() const { return hi - lo; }
};

Bounds mesh_bounds(const TriangleMesh& mesh);
double triangle_area(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);
double surface_area(const TriangleMesh& mesh);

}  // namespace ts::mesh
