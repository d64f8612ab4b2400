#include "core/blockers/sphere_cache.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/mesh/mesh_hash.hpp"
#include "core/util/atomic_file.hpp"
#include "core/util/error.hpp"

namespace ts::blockers {
namespace fs = std::filesystem;

namespace {
constexpr const char* kMagic = "terrashade-spheres";

std::string hex_double(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a", v);
    return buf;
}

bool read_double(std::istream& in, double& v) {
    std::string token;
    if (!(in >> token)) return false;
    char* end = nullptr;
    v = std::strtod(token.c_str(), &end);
    return end && *end == '\0';
}
}  // namespace

fs::path default_sphere_cache_dir() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "terrashade" / "spheres";
    if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".cache" / "terrashade" / "spheres";
    return fs::temp_directory_path() / "terrashade-cache" / "spheres";
}

std::string sphere_cache_name(std::uint64_t hash, const DecompositionOptions& o) {
    return mesh::hash_hex(hash) + "-n" + std::to_string(o.count) + "-r" + std::to_string(o.resolution) + "-p" +
           std::to_string(o.refine_passes) + "-s" + std::to_string(o.seed) + "-v" +
           std::to_string(kDecompositionVersion) + ".spheres";
}

std::optional<SphereDecomposition> load_cached_spheres(const fs::path& dir, std::uint64_t hash,
                                                       const DecompositionOptions& o) {
    std::ifstream in(dir / sphere_cache_name(hash, o));
    if (!in) return std::nullopt;
    std::string magic;
    int version = 0;
    std::size_t count = 0;
    SphereDecomposition d;
    if (!(in >> magic >> version) || magic != kMagic || version != kDecompositionVersion) return std::nullopt;
    if (!read_double(in, d.surface_coverage) || !read_double(in, d.excess_volume_ratio) || !read_double(in, d.seconds))
        return std::nullopt;
    if (!(in >> count) || count > std::size_t(kMaxSpheres)) return std::nullopt;
    d.spheres.resize(count);
    for (Sphere& s : d.spheres)
        if (!read_double(in, s.center.x) || !read_double(in, s.center.y) || !read_double(in, s.center.z) ||
            !read_double(in, s.radius) || !(s.radius >= 0.0))
            return std::nullopt;
    std::string end;
    if (!(in >> end) || end != "end") return std::nullopt;  // a truncated entry is a miss
    d.cached = true;
    return d;
}

void store_cached_spheres(const fs::path& dir, std::uint64_t hash, const DecompositionOptions& o,
                          const SphereDecomposition& d) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (!fs::is_directory(dir)) throw input_error(dir.string(), "cannot create the sphere cache folder");
    std::ostringstream text;
    text << kMagic << ' ' << kDecompositionVersion << '\n'
         << hex_double(d.surface_coverage) << ' ' << hex_double(d.excess_volume_ratio) << ' ' << hex_double(d.seconds)
         << '\n'
         << d.spheres.size() << '\n';
    for (const Sphere& s : d.spheres)
        text << hex_double(s.center.x) << ' ' << hex_double(s.center.y) << ' ' << hex_double(s.center.z) << ' '
             << hex_double(s.radius) << '\n';
    text << "end\n";
    const fs::path target = dir / sphere_cache_name(hash, o);
    write_atomically(target, [&](const fs::path& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out << text.str();
        if (!out.flush()) throw input_error(target.string(), "cannot write");
    });
}

SphereDecomposition decompose_cached(const mesh::TriangleMesh& mesh, const DecompositionOptions& o,
                                     const fs::path& cache_dir) {
    validate(o);
    if (cache_dir.empty()) return decompose_into_spheres(mesh, o);
    const std::uint64_t hash = mesh::geometry_hash(mesh);
    if (auto hit = load_cached_spheres(cache_dir, hash, o)) return *hit;
    SphereDecomposition d = decompose_into_spheres(mesh, o);
    store_cached_spheres(cache_dir, hash, o, d);
    return d;
}

}  // namespace ts::blockers
