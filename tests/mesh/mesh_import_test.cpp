// Import of the shared meshes through assimp: triangles, Z up, sizes in metres that match the
// real vehicles; and every bad input ends in one ts::InputError naming the file.
#include <set>
#include <string>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "core/mesh/mesh_import.hpp"
#include "core/util/error.hpp"
#include "tests/support/shared_data.hpp"

namespace {
namespace fs = std::filesystem;
using ts::mesh::import_mesh;

using ts::test::kCessna;
const std::string kTruck = std::string(TS_SHARED_DATA) + "/meshes/CesiumMilkTruck/CesiumMilkTruck.gltf";

// A folder per test process, removed when the process ends.
const fs::path& temp_root() {
    struct Root {
        fs::path path = fs::temp_directory_path() / ("ts_mesh_test_" + std::to_string(::getpid()));
        ~Root() {
            std::error_code ec;
            fs::remove_all(path, ec);
        }
    };
    static const Root root;
    return root.path;
}

fs::path temp_file(const std::string& name, const std::string& content) {
    fs::create_directories(temp_root());
    const fs::path p = temp_root() / name;
    std::ofstream(p, std::ios::binary) << content;
    return p;
}

// The message must name the file and be one line.
void expect_input_error(const fs::path& file, const std::string& fragment) {
    try {
        import_mesh(file);
        FAIL() << "no error for " << file;
    } catch (const ts::InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(file.string()), std::string::npos) << what;
        EXPECT_NE(what.find(fragment), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}

TEST(MeshImport, CessnaIsZUpInMetres) {
    const auto m = import_mesh(kCessna);
    EXPECT_GT(m.triangle_count(), 1000u);
    EXPECT_EQ(m.positions.size(), 3 * m.triangle_count());
    EXPECT_EQ(m.normals.size(), 3 * m.triangle_count());
    const auto size = ts::mesh::mesh_bounds(m).size();
    // A Cessna 172: about 8 m long, 10-11 m span, 2.7 m high. The file's y (its up) becomes z.
    EXPECT_NEAR(size.z, 2.6, 0.4);
    EXPECT_GT(std::max(size.x, size.y), 9.0);
    EXPECT_LT(std::max(size.x, size.y), 12.0);
    EXPECT_GT(std::min(size.x, size.y), 7.0);
    EXPECT_GE(m.materials.size(), 1u);
    for (auto idx : m.material) ASSERT_LT(idx, m.materials.size());
}

// What a simulator animates is left out: the propeller's blur disc (a solid dome in front of the
// nose without its see-through texture) and each light's lit twin; the blades, the unlit lights
// and everything else stay.
TEST(MeshImport, AnimatedAlternativesAreLeftOut) {
    const std::set<std::string> names = {"beaconoff", "beaconon", "leftnavlightoff", "leftnavlighton", "wingon"};
    for (const char* name : {"Propeller.Fast", "PropDisc", "prop_blur", "propeller_disk", "BeaconOn", "LeftNavLightOn"})
        EXPECT_TRUE(ts::mesh::is_animated_alternative(name, names)) << name;
    for (const char* name : {"Propeller", "Propeller.Slow", "BeaconOff", "LeftNavLightOff", "WingOn", "Fuselage", "Discus"})
        EXPECT_FALSE(ts::mesh::is_animated_alternative(name, names)) << name;
    // The Cessna's disc stood 0.9 m in front of its nose: without it the nose is the mesh's end.
    const auto m = import_mesh(kCessna);
    std::size_t disc = 0;  // triangles in the disc's plane (x = -1.79 in the file, 2 m across)
    for (const glm::vec3& p : m.positions) disc += std::abs(std::abs(p.x) - 1.793f) < 1e-3f && std::abs(p.z) > 0.9f;
    EXPECT_EQ(disc, 0u);
}

TEST(MeshImport, MilkTruckIsZUpInMetres) {
    const auto m = import_mesh(kTruck);
    EXPECT_GT(m.triangle_count(), 1000u);
    const auto b = ts::mesh::mesh_bounds(m);
    // glTF is Y-up: the truck's 2.6 m height goes to z, its wheels on z ~ 0.
    EXPECT_NEAR(b.size().z, 2.84, 0.3);
    EXPECT_NEAR(b.lo.z, -0.26, 0.1);
    EXPECT_NEAR(std::max(b.size().x, b.size().y), 4.87, 0.3);
    // Materials: the glTF 1 textured ones read white (their texture's factor).
    bool textured = false;
    for (const auto& mat : m.materials) textured |= !mat.base_color_texture.empty();
    EXPECT_TRUE(textured);
}

TEST(MeshImport, UpAxisCanBeForced) {
    ts::mesh::ImportOptions z_up;
    z_up.up = ts::mesh::UpAxis::z;
    const auto raw = import_mesh(kTruck, z_up);
    // Taken as Z-up, the file's y (height) stays y.
    EXPECT_NEAR(ts::mesh::mesh_bounds(raw).size().y, 2.84, 0.3);
}

TEST(MeshImport, OffIsZUpByDefault) {
    const auto p = temp_file("tri.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 0 2\n3 0 1 2\n");
    const auto m = import_mesh(p);
    ASSERT_EQ(m.triangle_count(), 1u);
    EXPECT_NEAR(ts::mesh::mesh_bounds(m).size().z, 2.0, 1e-6);
}

TEST(MeshImport, BadInputsNameTheFile) {
    expect_input_error(temp_root() / "no_such.obj", "no such file");
    expect_input_error(temp_file("empty.obj", ""), "empty file");
    expect_input_error(temp_file("text.gltf", "this is not a mesh at all\n"), "");
    expect_input_error(temp_file("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"), "no triangles");
    expect_input_error(temp_file("garbage.stl", std::string(300, '\x7f')), "");
    expect_input_error(fs::temp_directory_path(), "directory");
}

}  // namespace
