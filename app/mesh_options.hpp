#pragma once
// The mesh flags `render` and `relight` share: meshes standing over the DEM whose spheres
// shadow it (docs/blockers.md, "On the command line"). Parallel, repeatable options:
//
//   --mesh FILE --at LON,LAT,HEIGHT[agl] [--hpr H,P,R] [--scale S] [--spheres N]  (repeat per mesh)
//
// --mesh and --at pair by order (one --at per --mesh); --hpr, --scale and --spheres are given
// once for every mesh, or once per mesh in the same order, or not at all.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/dem/dem.hpp"
#include "core/mesh/placement.hpp"
#include "core/render/render_scene.hpp"

namespace ts::app {

struct MeshArgs {
    std::vector<std::string> files, at, hpr;
    std::vector<double> scale;
    std::vector<int> spheres;
    double min_solid_angle_sr = blockers::SphereBlockerOptions{}.min_solid_angle_sr;
    bool no_ratio_attenuation = false;
    bool no_hemisphere_cull = false;
    std::string sphere_culling = "none";  // SphereBlockerOptions::sky_culling
    std::string mesh_sun_shadow = "triangles";  // SphereBlockerOptions::sun_caster
    int mesh_sun_rays = blockers::SphereBlockerOptions{}.sun_rays;
    bool no_mesh_terrain_shadow = false;
    bool no_mesh_self_shadow = false;
    std::string cache_dir;
    std::string forward = "auto";  // --mesh-forward (app/options/mesh_forward_option.hpp)
};

struct MeshSpec {
    std::string file;
    mesh::Placement placement;
    int spheres = 64;
};

void add_mesh_options(CLI::App& cmd, MeshArgs& args);

// Every check that needs neither the DEM nor the mesh's content: pairing, numbers, ranges,
// files that exist. Throws ts::InputError (one line).
std::vector<MeshSpec> parse_mesh_specs(const MeshArgs& args);
blockers::SphereBlockerOptions blocker_options(const MeshArgs& args);

// Checks each placement lies on the DEM, then imports each mesh and takes its spheres from the
// cache (decomposing once on a miss); with spheres_later, none yet (--max-error chooses their
// count). Prints one line per mesh (and, verbose, the forward axis it assumed).
std::vector<render::SceneMesh> load_scene_meshes(const std::vector<MeshSpec>& specs, const dem::Dem& dem,
                                                 const MeshArgs& args, bool spheres_later = false, bool verbose = false);

}  // namespace ts::app
