// `terrashade spheres MESH --count N --out FILE.json [--preview FILE.png]`: the bounding sphere
// decomposition of a mesh (core/blockers/sphere_decomposition.hpp) as JSON, cached on disk by
// the mesh's geometry and the count, with a picture of mesh and spheres to check it by eye.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "app/command.hpp"
#include "app/io_plan.hpp"
#include "app/options/threads_option.hpp"
#include "app/sphere_preview.hpp"
#include "core/blockers/sphere_cache.hpp"
#include "core/blockers/sphere_decomposition.hpp"
#include "core/mesh/mesh_import.hpp"
#include "core/util/atomic_file.hpp"
#include "core/util/error.hpp"

namespace ts::app {
namespace {
namespace fs = std::filesystem;

struct SpheresArgs {
    std::string mesh;
    std::string out;
    std::string preview;
    std::string up = "auto";
    std::string cache_dir;
    bool no_cache = false;
    bool quiet = false;
    blockers::DecompositionOptions decomposition;
};

// An output's extension and folder are checked before any heavy work.
void check_output(const std::string& path, const std::string& extension, const std::string& what) {
    const fs::path p(path);
    if (p.extension() != extension) throw input_error(path, what + " must be a " + extension + " file");
    const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw input_error(path, "output directory does not exist");
}

nlohmann::json to_json(const std::string& mesh_path, const mesh::TriangleMesh& mesh,
                       const blockers::SphereDecomposition& d) {
    nlohmann::json spheres = nlohmann::json::array();
    for (const blockers::Sphere& s : d.spheres)
        spheres.push_back({{"center", {s.center.x, s.center.y, s.center.z}}, {"radius", s.radius}});
    const mesh::Bounds b = mesh::mesh_bounds(mesh);
    return {{"mesh", mesh_path},
            {"frame", "normalised model frame: x, y horizontal, z up, metres"},
            {"triangles", mesh.triangle_count()},
            {"bounds", {{"min", {b.lo.x, b.lo.y, b.lo.z}}, {"max", {b.hi.x, b.hi.y, b.hi.z}}}},
            {"count", d.spheres.size()},
            {"surface_coverage", d.surface_coverage},
            {"excess_volume_ratio", d.excess_volume_ratio},
            {"seconds", d.seconds},
            {"cached", d.cached},
            {"spheres", spheres}};
}

void run_spheres(const SpheresArgs& a) {
    // Everything cheap first: options, output names, then the mesh (import is fast).
    blockers::validate(a.decomposition);
    check_output(a.out, ".json", "--out");
    if (!a.preview.empty()) check_output(a.preview, ".png", "--preview");
    IoPlan plan;
    plan.input("mesh", a.mesh).output("--out", a.out, {".json"}).output("--preview", a.preview, {".png"});
    plan.check();
    mesh::ImportOptions import;
    import.up = mesh::parse_up_axis(a.up);
    const mesh::TriangleMesh mesh = mesh::import_mesh(a.mesh, import);

    const fs::path cache = a.no_cache ? fs::path() : a.cache_dir.empty() ? blockers::default_sphere_cache_dir()
                                                                          : fs::path(a.cache_dir);
    const blockers::SphereDecomposition d = blockers::decompose_cached(mesh, a.decomposition, cache);

    const std::string text = to_json(a.mesh, mesh, d).dump(1) + "\n";
    write_atomically(a.out, [&](const fs::path& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        if (!out.flush()) throw input_error(a.out, "cannot write");
    });
    if (!a.preview.empty()) write_sphere_preview(a.preview, mesh, d.spheres);
    if (!a.quiet)
        std::printf("%zu spheres, surface coverage %.4f, excess volume ratio %.3f, %.2f s%s -> %s\n", d.spheres.size(),
                    d.surface_coverage, d.excess_volume_ratio, d.seconds, d.cached ? " (cached)" : "", a.out.c_str());
}

}  // namespace

void add_spheres_command(CLI::App& root) {
    auto a = std::make_shared<SpheresArgs>();
    CLI::App* cmd = root.add_subcommand(
        "spheres",
        "Bounding sphere decomposition of a mesh (AC3D, glTF, OBJ, STL, PLY, OFF, 3DS, FBX, ...): spheres holding "
        "its whole surface with little volume outside it, as JSON in the normalised model frame (Z up, metres)");
    cmd->add_option("mesh", a->mesh, "Mesh file")->required();
    cmd->add_option("-n,--count", a->decomposition.count, "Number of spheres, 8..512")->capture_default_str();
    cmd->add_option("-o,--out", a->out, "Output JSON (written atomically)")->required();
    cmd->add_option("--preview", a->preview, "Also draw mesh and spheres in three orthographic views (.png)");
    cmd->add_option("--up", a->up, "The file's up axis: auto (header, else by format), x, y, z")->capture_default_str();
    cmd->add_option("--resolution", a->decomposition.resolution, "Voxel cells along the mesh's longest side, 16..512")
        ->capture_default_str();
    add_threads_option(*cmd, a->decomposition.threads);
    cmd->add_option("--cache-dir", a->cache_dir,
                    "Sphere cache folder (default $XDG_CACHE_HOME/terrashade/spheres or ~/.cache/terrashade/spheres)");
    cmd->add_flag("--no-cache", a->no_cache, "Neither read nor write the cache");
    cmd->add_flag("-q,--quiet", a->quiet, "No summary line on stdout");
    cmd->callback([a] { run_spheres(*a); });
}

}  // namespace ts::app
