#pragma once
// What a mesh importer found in a file, as plain data: the node tree with its transforms, the
// meshes' vertices, normals and triangles, the materials and the header's up axis. assimp
// fills it in a child process (mesh_import.cpp) and hands it over as bytes; the parent decodes
// those bytes as untrusted input (every count and index is checked against what the bytes can
// hold) and flattens the tree into a TriangleMesh (scene_flattening.hpp).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/mesh/triangle_mesh.hpp"

namespace ts::mesh {

struct ImportedMesh {
    std::vector<glm::vec3> vertices;
    std::vector<glm::vec3> normals;        // empty, or one per vertex
    std::vector<std::uint32_t> triangles;  // three vertex indices per triangle
    std::uint32_t material = 0;
};

struct ImportedNode {
    glm::dmat4 transform{1.0};            // to the parent's frame
    std::vector<std::uint32_t> meshes;    // indices into ImportedScene::meshes
    std::vector<std::uint32_t> children;  // indices into ImportedScene::nodes
};

struct ImportedScene {
    std::vector<ImportedNode> nodes;  // nodes[0] is the root
    std::vector<ImportedMesh> meshes;
    std::vector<MeshMaterial> materials;
    int header_up_axis = -1;  // 0, 1, 2 = x, y, z as the file's header declares; -1 = none
    int header_up_sign = 1;
};

std::vector<std::uint8_t> encode_scene(const ImportedScene& scene);
// Throws ts::InputError naming `shown` when the bytes are not a whole, consistent record.
ImportedScene decode_scene(const std::uint8_t* data, std::size_t size, const std::string& shown);

}  // namespace ts::mesh
