#pragma once
// Mesh import through assimp (AC3D, glTF 1/2, OBJ, STL, PLY, OFF, 3DS, FBX, Collada and the
// rest it reads): triangles with every node transform applied, normalised to Z-up metres,
// and the materials' base colours. Points and lines are dropped; polygons are triangulated.
#include <cstdint>
#include <filesystem>

#include "core/mesh/triangle_mesh.hpp"
#include "core/mesh/up_axis.hpp"

namespace ts::mesh {

struct ImportOptions {
    UpAxis up = UpAxis::automatic;  // automatic: the file's header, else its extension (up_axis.hpp)
    double unit_scale = 1.0;        // metres per file unit, for files not in metres (FBX is converted)
    // assimp reads the file in a child process (core/util/isolated_call.hpp): a parser crash,
    // hang or runaway allocation on a malformed file is then one error, not the end of the
    // command. The child is killed after timeout_s seconds and may allocate memory_bytes; 0
    // picks them from the file's size: 10 s + 2 s per MB, 512 MB + 100x the file (real meshes
    // parse at tens of MB/s into a few times their size), never more than is available.
    double timeout_s = 0;
    std::uint64_t memory_bytes = 0;
};

// Throws ts::InputError, one line naming the file, when it is missing, empty, unreadable,
// not a mesh, holds no triangle, or crashes or hangs the importer.
TriangleMesh import_mesh(const std::filesystem::path& file, const ImportOptions& options = {});

}  // namespace ts::mesh
