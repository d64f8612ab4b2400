#include "app/mesh_options.hpp"

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <string_view>

#include "app/options/mesh_forward_option.hpp"
#include "app/options/quantity_flags.hpp"
#include "core/blockers/sphere_cache.hpp"
#include "core/blockers/sphere_decomposition.hpp"
#include "core/mesh/mesh_import.hpp"
#include "core/util/error.hpp"
#include "app/options/within_range.hpp"

namespace ts::app {
namespace {

bool parse_double(std::string_view s, double& out) {
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return !s.empty() && ec == std::errc() && p == s.data() + s.size() && std::isfinite(out);
}

// "a,b,c" -> three numbers; `suffix` (e.g. "agl") may end the last one and is reported.
bool parse_triple(std::string_view text, double v[3], std::string_view suffix, bool* had_suffix) {
    if (had_suffix) *had_suffix = false;
    for (int i = 0; i < 3; ++i) {
        const auto comma = text.find(',');
        if ((i < 2) == (comma == text.npos)) return false;
        std::string_view item = text.substr(0, comma);
        if (i == 2 && !suffix.empty() && item.ends_with(suffix)) {
            item.remove_suffix(suffix.size());
            if (had_suffix) *had_suffix = true;
        }
        if (!parse_double(item, v[i])) return false;
        text = comma == text.npos ? std::string_view() : text.substr(comma + 1);
    }
    return true;
}

// Option `name` given `given` times for `meshes` meshes: 0, 1 (all) or one each.
void check_count(const char* name, std::size_t given, std::size_t meshes) {
    if (given > 1 && given != meshes)
        throw InputError(std::string(name) + ": give it once for every mesh or once per --mesh (" +
                         std::to_string(meshes) + "), got " + std::to_string(given));
}

template <class T>
const T* nth_or_only(const std::vector<T>& v, std::size_t k) {
    if (v.empty()) return nullptr;
    return v.size() == 1 ? &v[0] : &v[k];
}

}  // namespace

void add_mesh_options(CLI::App& cmd, MeshArgs& a) {
    auto one_each = [](CLI::Option* o) { o->expected(1)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll); };
    one_each(cmd.add_option("--mesh", a.files,
                            "A mesh standing over the DEM (any format assimp reads); repeatable, each with its --at. "
                            "Its bounding spheres shadow the terrain's sky and sun (docs/blockers.md)"));
    one_each(cmd.add_option("--at", a.at,
                            "Where the mesh's origin stands: LON,LAT,HEIGHT (degrees, metres above the DEM's datum; "
                            "HEIGHTagl: above the terrain there), one per --mesh, in order"));
    one_each(cmd.add_option("--hpr", a.hpr,
                            "Heading,pitch,roll in degrees (heading: the nose, --mesh-forward, clockwise from north; "
                            "pitch nose up; roll right side down); once for all meshes or once per --mesh"));
    one_each(cmd.add_option("--scale", a.scale, "Uniform scale of the mesh (> 0; once for all or once per --mesh)"));
    one_each(cmd.add_option("--spheres", a.spheres,
                            "Bounding spheres per mesh, 8..512 (default 64; cached on disk; once for all or per --mesh)"));
    add_mesh_forward_option(cmd, a.forward);
    cmd.add_option("--blocker-min-solid-angle", a.min_solid_angle_sr,
                   "A mesh darkens a texel's sky only while its bounding sphere subtends more than this many steradians there")
        ->capture_default_str()
        ->check(within(1e-6, 1.0));
    cmd.add_flag("--no-ratio-attenuation", a.no_ratio_attenuation,
                 "Sum the spheres' log-SH unweighted (default: scaled so the kept caps claim at most the hemisphere)");
    cmd.add_flag("--no-hemisphere-cull", a.no_hemisphere_cull,
                 "Keep spheres wholly below a texel's tangent plane (default: dropped)");
    cmd.add_option("--sphere-culling", a.sphere_culling,
                   "How a texel picks the spheres that darken its sky: hierarchy (the sphere hierarchy with "
                   "--blocker-min-solid-angle as a level of detail) or none (every sphere of a mesh whose bounding "
                   "sphere passes it)")
        ->capture_default_str()
        ->check(CLI::IsMember({"hierarchy", "none"}));
    cmd.add_option("--mesh-sun-shadow", a.mesh_sun_shadow,
                   "What casts a mesh's sun shadow on the terrain: triangles (rays through its own triangles over "
                   "the sun's disc, where its spheres shadow) or spheres (their analytic cover of the disc)")
        ->capture_default_str()
        ->check(CLI::IsMember({"triangles", "spheres"}));
    cmd.add_option("--mesh-sun-rays", a.mesh_sun_rays,
                   "Rays per texel over the sun's disc with --mesh-sun-shadow triangles (the penumbra's steps)")
        ->capture_default_str()
        ->check(within(1, 256));
    cmd.add_flag("--no-mesh-terrain-shadow", a.no_mesh_terrain_shadow,
                 "Perspective views: light the drawn meshes under the open sky (default: the terrain's horizons from "
                 "each vertex darken them and hide the sun)");
    cmd.add_flag("--no-mesh-self-shadow", a.no_mesh_self_shadow,
                 "Perspective views: the drawn meshes are not shadowed by their own spheres (default: they are)");
    cmd.add_option("--sphere-cache-dir", a.cache_dir,
                   "Where sphere decompositions are cached (default $XDG_CACHE_HOME/terrashade/spheres)");
}

std::vector<MeshSpec> parse_mesh_specs(const MeshArgs& a) {
    const std::size_t n = a.files.size();
    if (a.at.size() != n)
        throw InputError("--mesh and --at go in pairs: " + std::to_string(n) + " --mesh, " +
                         std::to_string(a.at.size()) + " --at");
    check_count("--hpr", a.hpr.size(), n);
    check_count("--scale", a.scale.size(), n);
    check_count("--spheres", a.spheres.size(), n);
    if (n == 0 && (!a.hpr.empty() || !a.scale.empty() || !a.spheres.empty()))
        throw InputError("--hpr, --scale and --spheres go with --mesh");
    std::vector<MeshSpec> specs;
    for (std::size_t k = 0; k < n; ++k) {
        MeshSpec s;
        s.file = a.files[k];
        std::error_code ec;
        if (!std::filesystem::is_regular_file(s.file, ec)) throw input_error(s.file, "--mesh: no such file");
        double v[3];
        bool agl = false;
        if (!parse_triple(a.at[k], v, "agl", &agl))
            throw InputError("--at " + a.at[k] + ": give LON,LAT,HEIGHT or LON,LAT,HEIGHTagl (e.g. 5.72,45.19,300agl)");
        s.placement.lon_deg = v[0], s.placement.lat_deg = v[1], s.placement.height_m = v[2];
        s.placement.above_ground = agl;
        if (const std::string* hpr = nth_or_only(a.hpr, k)) {
            if (!parse_triple(*hpr, v, "", nullptr))
                throw InputError("--hpr " + *hpr + ": give HEADING,PITCH,ROLL in degrees (e.g. 90,0,0)");
            s.placement.heading_deg = v[0], s.placement.pitch_deg = v[1], s.placement.roll_deg = v[2];
        }
        s.placement.forward_yaw_deg = mesh::forward_yaw_deg(mesh_forward_axis(a.forward, s.file));
        if (const double* scale = nth_or_only(a.scale, k)) s.placement.scale = *scale;
        if (const int* count = nth_or_only(a.spheres, k)) s.spheres = *count;
        try {
            mesh::validate(s.placement);
            blockers::DecompositionOptions d;
            d.count = s.spheres;
            blockers::validate(d);
        } catch (const QuantityError& e) {
            throw input_error(s.file, flag_message(e, "render"));
        } catch (const InputError& e) {
            throw input_error(s.file, e.what());
        }
        specs.push_back(s);
    }
    return specs;
}

blockers::SphereBlockerOptions blocker_options(const MeshArgs& a) {
    blockers::SphereBlockerOptions o;
    o.min_solid_angle_sr = a.min_solid_angle_sr;
    o.attenuation.solid_angle_ratio = !a.no_ratio_attenuation;
    o.attenuation.cull_lower_hemisphere = !a.no_hemisphere_cull;
    o.sky_culling = a.sphere_culling == "hierarchy" ? blockers::SphereBlockerOptions::SkyCulling::hierarchy
                                                    : blockers::SphereBlockerOptions::SkyCulling::none;
    o.sun_caster = a.mesh_sun_shadow == "spheres" ? blockers::SphereBlockerOptions::SunCaster::spheres
                                                  : blockers::SphereBlockerOptions::SunCaster::triangles;
    o.sun_rays = a.mesh_sun_rays;
    return o;
}

std::vector<render::SceneMesh> load_scene_meshes(const std::vector<MeshSpec>& specs, const dem::Dem& dem,
                                                 const MeshArgs& a, bool spheres_later, bool verbose) {
    for (const MeshSpec& s : specs) render::mesh_anchor(dem.georef, s.placement, s.file);  // off the DEM: exit 2 now
    const std::filesystem::path cache =
        a.cache_dir.empty() ? blockers::default_sphere_cache_dir() : std::filesystem::path(a.cache_dir);
    std::vector<render::SceneMesh> meshes;
    for (const MeshSpec& s : specs) {
        const mesh::TriangleMesh m = mesh::import_mesh(s.file, {});
        if (verbose) std::printf("mesh %s: %s\n", s.file.c_str(), describe_mesh_forward(a.forward, s.file).c_str());
        std::vector<blockers::Sphere> spheres;
        if (spheres_later) {
            std::printf("mesh %s: %zu triangles, scale %g (its spheres: --max-error chooses how many)\n", s.file.c_str(),
                        m.triangle_count(), s.placement.scale);
        } else {
            blockers::DecompositionOptions d;
            d.count = s.spheres;
            const blockers::SphereDecomposition sd = blockers::decompose_cached(m, d, cache);
            std::printf("mesh %s: %zu triangles, %zu spheres (%s), scale %g\n", s.file.c_str(), m.triangle_count(),
                        sd.spheres.size(), sd.cached ? "cached" : "decomposed now", s.placement.scale);
            spheres = sd.spheres;
        }
        meshes.push_back({s.file, s.placement, std::move(spheres), std::make_shared<const mesh::TriangleMesh>(m)});
    }
    return meshes;
}

}  // namespace ts::app
