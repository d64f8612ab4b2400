#pragma once
// How a fuzz input's bytes reach the mesh import, shared by the libFuzzer targets
// (fuzz_mesh_file.cpp, fuzz_mesh_scene.cpp) and the GoogleTest that replays the seeds and every
// input once found to crash or hang (tests/mesh/mesh_fuzz_regressions_test.cpp).
#include <cstddef>
#include <cstdint>
#include <string>

namespace ts::fuzz {

enum class MeshOutcome { read, input_error };

// A mesh file: byte 0 picks the file's extension (mesh_extensions, modulo their count: assimp
// chooses its parser by it), the rest is the file, imported by ts::mesh::import_mesh (assimp in
// a child process, its result decoded and flattened in this one).
MeshOutcome feed_mesh_file(const std::uint8_t* data, std::size_t size);
// The bytes as the child process's scene record (imported_scene.hpp), decoded and flattened:
// the part of the import that runs in terrashade's own process, fuzzed without the parser.
MeshOutcome feed_mesh_scene(const std::uint8_t* data, std::size_t size);

// ".obj", ".stl", ...: the extensions feed_mesh_file gives, indexed by byte 0.
const char* mesh_extension(std::uint8_t selector);

using MeshFeed = MeshOutcome (*)(const std::uint8_t*, std::size_t);
// "mesh_file" or "mesh_scene"; nullptr otherwise.
MeshFeed mesh_feed_for(const std::string& target);

}  // namespace ts::fuzz
