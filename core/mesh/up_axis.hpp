#pragma once
// Which axis of a file points up, and the rotation that makes it Z. assimp leaves coordinates
// as the file has them, except that some loaders (3DS, Collada) already convert to its own
// Y-up convention; so Y is up for what comes through those and for the Y-up formats (glTF, by
// its specification; AC3D and OBJ, by the habit of their tools), and Z for the CAD and scanning
// formats (STL, PLY, OFF). FBX says in its header (UpAxis, UpAxisSign), which wins when present.
#include <string>

#include <glm/mat3x3.hpp>

namespace ts::mesh {

enum class UpAxis { automatic, x, y, z };

// "auto", "x", "y", "z" (case-insensitive); throws ts::InputError otherwise.
UpAxis parse_up_axis(const std::string& text);
// The up axis a file's extension implies when its header says nothing (".stl" -> z, ".gltf" -> y).
UpAxis default_up_axis(const std::string& extension);
// The proper rotation (det +1) taking `up` (negated when up_sign < 0) to +Z.
glm::dmat3 to_z_up(UpAxis up, int up_sign = 1);

}  // namespace ts::mesh
