#pragma once
// A 64-bit content hash of a mesh's geometry (the normalised positions, in order): the key
// under which derived data (the sphere decompositions) is cached. Materials and normals are
// left out: they do not change the geometry.
#include <cstdint>
#include <string>

#include "core/mesh/triangle_mesh.hpp"

namespace ts::mesh {

std::uint64_t geometry_hash(const TriangleMesh& mesh);
// 16 lower-case hex digits.
std::string hash_hex(std::uint64_t hash);

}  // namespace ts::mesh
