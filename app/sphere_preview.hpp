#pragma once
// A picture to judge a sphere decomposition by eye: the mesh in three orthographic views side
// by side (top: x right, y up; front: x right, z up; side: y right, z up), shaded grey by its
// normals with a depth buffer, over translucent discs of the spheres, their outlines on top.
#include <filesystem>
#include <span>

#include "core/blockers/sphere_blocker.hpp"
#include "core/mesh/triangle_mesh.hpp"

namespace ts::app {

// Written atomically. panel_size: pixels per view (square).
void write_sphere_preview(const std::filesystem::path& png, const mesh::TriangleMesh& mesh,
                          std::span<const blockers::Sphere> spheres, int panel_size = 480);

}  // namespace ts::app
