#pragma once
// Mesh import through assimp (AC3D, glTF 1/2, OBJ, STL, PLY, OFF, 3DS, FBX, Collada and the
// rest it reads): triangles with every node transform applied, normalised to Z-up metres,
// and the materials' base colours. Points and lines are dropped; polygons are triangulated.
#include <cstdint>
#include <filesystem>
#include <set>
#include <string>

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

// A flight simulator's model holds alternatives its animations choose between: a propeller's
// blades and its blur disc, each light unlit and lit. terrashade animates nothing, so it keeps
// the blades and the unlit lights and leaves out the nodes this names: a propeller's disc
// ("prop" with ".fast", "disc", "disk" or "blur" in the name, as FlightGear's Propeller.Fast)
// and a lit light beside its unlit twin (X + "On" where X + "Off" is in `names`, lower case).
// Drawn, the c172p's disc was a solid 2 m dome in front of the nose (its see-through texture is
// not shipped), dark in its own spheres' shadow.
bool is_animated_alternative(const std::string& name, const std::set<std::string>& names);

}  // namespace ts::mesh
