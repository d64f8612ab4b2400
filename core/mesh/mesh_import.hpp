#pragma once
// Mesh import through assimp (AC3D, glTF 1/2, OBJ, STL, PLY, OFF, 3DS, FBX, Collada and the
// rest it reads): triangles with every node transform applied, normalised to Z-up metres,
// and the materials' base colours. Points and lines are dropped; polygons are triangulated.
#include <filesystem>

#include "core/mesh/triangle_mesh.hpp"
#include "core/mesh/up_axis.hpp"

namespace ts::mesh {

struct ImportOptions {
    UpAxis up = UpAxis::automatic;  // automatic: the file's header, else its extension (up_axis.hpp)
    double unit_scale = 1.0;        // metres per file unit, for files not in metres (FBX is converted)
};

// Throws ts::InputError, one line naming the file, when it is missing, empty, unreadable,
// not a mesh, or holds no triangle.
TriangleMesh import_mesh(const std::filesystem::path& file, const ImportOptions& options = {});

}  // namespace ts::mesh
