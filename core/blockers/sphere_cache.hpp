#pragma once
// Sphere decompositions on disk, so a mesh is decomposed once per sphere count. The key is the
// mesh's geometry hash (core/mesh/mesh_hash.hpp), the count, every option that changes the
// spheres (resolution, refinement passes, seed) and kDecompositionVersion; the file holds the
// spheres as hexadecimal floats, so a hit returns exactly the spheres computed. Written to a
// temporary sibling and renamed; an unreadable or foreign entry is a miss, never an error.
#include <filesystem>
#include <optional>
#include <string>

#include "core/blockers/sphere_decomposition.hpp"

namespace ts::blockers {

// $XDG_CACHE_HOME/terrashade/spheres, else $HOME/.cache/terrashade/spheres, else a folder in
// the system's temporary directory.
std::filesystem::path default_sphere_cache_dir();

// The entry's file name: <hash>-n<count>-r<resolution>-p<passes>-s<seed>-v<version>.spheres
std::string sphere_cache_name(std::uint64_t geometry_hash, const DecompositionOptions& options);

std::optional<SphereDecomposition> load_cached_spheres(const std::filesystem::path& dir, std::uint64_t geometry_hash,
                                                       const DecompositionOptions& options);
// Creates `dir` as needed. Throws ts::InputError (naming the file) when it cannot write.
void store_cached_spheres(const std::filesystem::path& dir, std::uint64_t geometry_hash,
                          const DecompositionOptions& options, const SphereDecomposition& decomposition);

// Loads the entry, or decomposes and stores it (cache_dir empty: no cache).
SphereDecomposition decompose_cached(const mesh::TriangleMesh& mesh, const DecompositionOptions& options,
                                     const std::filesystem::path& cache_dir);

}  // namespace ts::blockers
