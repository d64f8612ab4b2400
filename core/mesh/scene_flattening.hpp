#pragma once
// The triangle soup of an imported scene: every mesh of every node with the node's transforms
// (root first) applied, normals through the inverse transpose, in the frame `root` maps to.
// The scene is untrusted (it crossed a process boundary): a node or mesh index out of range,
// a node reached twice or a vertex index out of range is one ts::InputError naming `shown`.
// Triangles with a corner that is not finite are dropped; materials out of range fall to 0.
#include <string>

#include <glm/mat4x4.hpp>

#include "core/mesh/imported_scene.hpp"
#include "core/mesh/triangle_mesh.hpp"

namespace ts::mesh {

TriangleMesh flatten_scene(const ImportedScene& scene, const glm::dmat4& root, const std::string& shown);

}  // namespace ts::mesh
