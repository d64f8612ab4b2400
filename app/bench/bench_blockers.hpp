#pragma once
// `terrashade bench blockers` (bench_blockers_command.cpp), its moving-aircraft part
// (bench_blockers_motion.cpp) and its part on the mesh itself (bench_blockers_self.cpp).
#include <span>
#include <string>
#include <vector>

#include "core/blockers/sphere_decomposition.hpp"
#include "core/mesh/triangle_mesh.hpp"

namespace ts::app {

struct BenchBlockersOptions {
    std::string dem = "../shared/data/dem/srtm3_N39E040_1000px.tif";
    std::string mesh = "../shared/data/meshes/c172p.ac";
    std::vector<double> at = {40.40, 39.60, 600.0};  // lon, lat, metres above the ground
    std::vector<double> hpr = {60.0, 0.0, 0.0};
    double scale = 200.0;  // the 9.6 m Cessna is a tenth of a 90 m texel: scaled to span ~20
    double sun_az = 240.0, sun_el = 30.0;
    std::vector<int> counts = {8, 16, 32, 64, 128, 256, 512};
    int directions = 32;
    int sky_strata = 24;
    int sun_samples = 64;
    int threads = 2;
    std::string sphere_culling = "none";  // of the accuracy part (the motion part runs both)
    std::string csv;
    // The moving aircraft: spheres over a 1000 x 1000 DEM, frames along a straight path.
    std::string motion_dem = "../shared/data/dem/srtm3_N39E040_1000px.tif";
    int motion_spheres = 400;
    int motion_frames = 8;
    bool motion_only = false;  // the moving aircraft alone (bench report's culling study)
};

// Per-frame cost of the mesh moving over motion_dem: the footprints of the old and new place
// recomputed through the sphere hierarchy, against every sphere tested at every footprint
// texel (no hierarchy), and the sphere-texel pairs per second of both.
void run_blocker_motion_bench(const BenchBlockersOptions& o);

// The mesh's self-shadow from each decomposition's spheres against its triangles ray-traced:
// sky visibility about the surface's normals and the sun's disc, on each side of every face.
void run_blocker_self_bench(const mesh::TriangleMesh& mesh, std::span<const blockers::SphereDecomposition> sets,
                            int threads);

}  // namespace ts::app
