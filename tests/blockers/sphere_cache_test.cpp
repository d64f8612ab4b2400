// The sphere cache: a second request is a hit with exactly the same spheres; another count, a
// changed mesh or a corrupt entry is a miss.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "core/blockers/sphere_cache.hpp"
#include "core/mesh/mesh_hash.hpp"
#include "core/mesh/mesh_import.hpp"

namespace {
namespace fs = std::filesystem;

struct TempDir {
    fs::path path = fs::temp_directory_path() / ("ts_sphere_cache_" + std::to_string(::getpid()));
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

TEST(SphereCache, HitReturnsIdenticalSpheres) {
    const TempDir dir;
    const auto mesh = ts::mesh::import_mesh(std::filesystem::path(TS_SHARED_DATA) / "meshes" / "CesiumMilkTruck" / "CesiumMilkTruck.gltf");
    ts::blockers::DecompositionOptions o;
    o.count = 16;
    o.threads = 2;
    const auto first = ts::blockers::decompose_cached(mesh, o, dir.path);
    EXPECT_FALSE(first.cached);
    const auto second = ts::blockers::decompose_cached(mesh, o, dir.path);
    EXPECT_TRUE(second.cached);
    ASSERT_EQ(first.spheres.size(), second.spheres.size());
    for (std::size_t i = 0; i < first.spheres.size(); ++i) {
        EXPECT_EQ(first.spheres[i].center, second.spheres[i].center);
        EXPECT_EQ(first.spheres[i].radius, second.spheres[i].radius);
    }
    EXPECT_EQ(first.surface_coverage, second.surface_coverage);
    EXPECT_EQ(first.excess_volume_ratio, second.excess_volume_ratio);

    // Another count is another entry.
    auto other = o;
    other.count = 17;
    EXPECT_FALSE(ts::blockers::load_cached_spheres(dir.path, ts::mesh::geometry_hash(mesh), other).has_value());
    // A truncated entry is a miss, not an error.
    const fs::path entry = dir.path / ts::blockers::sphere_cache_name(ts::mesh::geometry_hash(mesh), o);
    ASSERT_TRUE(fs::exists(entry));
    fs::resize_file(entry, fs::file_size(entry) / 2);
    EXPECT_FALSE(ts::blockers::load_cached_spheres(dir.path, ts::mesh::geometry_hash(mesh), o).has_value());
    // No temporary files left behind.
    int files = 0;
    for (const auto& e : fs::directory_iterator(dir.path)) files += e.is_regular_file();
    EXPECT_EQ(files, 1);
}

}  // namespace
