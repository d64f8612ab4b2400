// A mesh's heading means the same for every format (core/mesh/forward_axis.hpp): with the
// default forward axis of its format, heading 90 puts the nose east, for FlightGear's AC3D
// Cessna (nose -x, Y up in the file) and for a glTF 2.0 dart written here (front +Z, Y up, as
// the glTF spec has it). The nose is found from the model itself, not from the convention: the
// Cessna's fin top is aft; the dart's tip is its front.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/mesh/forward_axis.hpp"
#include "core/mesh/mesh_import.hpp"
#include "core/mesh/placement.hpp"
#include <glm/geometric.hpp>
#include "core/util/error.hpp"
#include "tests/support/shared_data.hpp"

namespace {
namespace fs = std::filesystem;
using namespace ts::mesh;

using ts::test::kCessna;

glm::dvec3 centroid(const TriangleMesh& m) {
    glm::dvec3 c(0.0);
    for (const glm::vec3& p : m.positions) c += glm::dvec3(p);
    return c / double(m.positions.size());
}

// The mean of the vertices within `band` metres of the highest one.
glm::dvec3 top(const TriangleMesh& m, double band) {
    double z_max = -1e30;
    for (const glm::vec3& p : m.positions) z_max = std::max(z_max, double(p.z));
    glm::dvec3 s(0.0);
    int n = 0;
    for (const glm::vec3& p : m.positions)
        if (p.z >= z_max - band) s += glm::dvec3(p), ++n;
    return s / double(n);
}

// ENU direction (unit, horizontal) from `from` to `to` in the model frame, after the placement.
glm::dvec3 placed_direction(const Placement& p, const glm::dvec3& from, const glm::dvec3& to) {
    glm::dvec3 d = placement_rotation(p) * (to - from);
    d.z = 0;
    return d / std::sqrt(d.x * d.x + d.y * d.y);
}

Placement heading_90_for(const std::string& file) {
    Placement p;
    p.heading_deg = 90.0;
    p.forward_yaw_deg = forward_yaw_deg(default_forward_axis(fs::path(file).extension().string()));
    return p;
}

TEST(MeshHeading, TheCessnaFliesEastAtHeading90) {
    const TriangleMesh m = import_mesh(kCessna);
    const glm::dvec3 c = centroid(m), fin = top(m, 0.05);
    // The data as it is: the fin top is aft, towards +x, so the nose is -x.
    ASSERT_GT(fin.x - c.x, 1.0) << "the fin top should be well aft of the centroid";
    EXPECT_EQ(default_forward_axis(".ac"), ForwardAxis::minus_x);
    const glm::dvec3 aft = placed_direction(heading_90_for(kCessna), c, fin);
    EXPECT_LT(aft.x, -0.95) << "the tail points west, so the nose east";
    EXPECT_NEAR(aft.y, 0.0, 0.3);
    // heading 0: the nose north.
    Placement north = heading_90_for(kCessna);
    north.heading_deg = 0.0;
    EXPECT_LT(placed_direction(north, c, fin).y, -0.95);
}

// A dart with its tip at +Z (glTF's front), Y up, as non-indexed triangles in a .bin beside.
fs::path write_gltf_dart(const fs::path& dir) {
    fs::create_directories(dir);
    const float tip[3] = {0, 0, 2}, a[3] = {-0.5f, 0, -1}, b[3] = {0.5f, 0, -1}, c[3] = {0, 0.5f, -1};
    const float* tris[4][3] = {{tip, a, b}, {tip, b, c}, {tip, c, a}, {a, c, b}};
    std::vector<float> v;
    for (auto& t : tris)
        for (const float* p : t) v.insert(v.end(), p, p + 3);
    std::ofstream(dir / "dart.bin", std::ios::binary).write(reinterpret_cast<const char*>(v.data()),
                                                             std::streamsize(v.size() * sizeof(float)));
    const std::string gltf = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
"buffers":[{"uri":"dart.bin","byteLength":)" + std::to_string(v.size() * 4) + R"(}],
"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":)" + std::to_string(v.size() * 4) + R"(}],
"accessors":[{"bufferView":0,"componentType":5126,"count":12,"type":"VEC3","min":[-0.5,0,-1],"max":[0.5,0.5,2]}]})";
    std::ofstream(dir / "dart.gltf") << gltf;
    return dir / "dart.gltf";
}

TEST(MeshHeading, AGltfDartFliesEastAtHeading90) {
    const fs::path file = write_gltf_dart(fs::temp_directory_path() / ("ts_mesh_heading_" + std::to_string(::getpid())));
    const TriangleMesh m = import_mesh(file);
    fs::remove_all(file.parent_path());
    ASSERT_EQ(m.triangle_count(), 4u);
    // The tip: the vertex farthest from the centroid.
    const glm::dvec3 c = centroid(m);
    glm::dvec3 tip = c;
    for (const glm::vec3& p : m.positions)
        if (glm::length(glm::dvec3(p) - c) > glm::length(tip - c)) tip = glm::dvec3(p);
    EXPECT_EQ(default_forward_axis(".gltf"), ForwardAxis::minus_y);
    EXPECT_EQ(default_forward_axis(".GLB"), ForwardAxis::minus_y);
    const glm::dvec3 nose = placed_direction(heading_90_for(file.string()), c, tip);
    EXPECT_GT(nose.x, 0.95) << "the tip points east";
    EXPECT_NEAR(nose.y, 0.0, 0.2);
}

TEST(MeshHeading, TheForwardAxisParsesItsFourNamesOnly) {
    EXPECT_EQ(parse_forward_axis("+x"), ForwardAxis::plus_x);
    EXPECT_EQ(parse_forward_axis("-y"), ForwardAxis::minus_y);
    EXPECT_THROW(parse_forward_axis("z"), ts::InputError);
    // The yaw turns the named axis onto +y.
    for (ForwardAxis a : {ForwardAxis::plus_x, ForwardAxis::minus_x, ForwardAxis::plus_y, ForwardAxis::minus_y}) {
        Placement p;
        p.forward_yaw_deg = forward_yaw_deg(a);
        const glm::dvec3 axis = a == ForwardAxis::plus_x    ? glm::dvec3(1, 0, 0)
                                : a == ForwardAxis::minus_x ? glm::dvec3(-1, 0, 0)
                                : a == ForwardAxis::plus_y  ? glm::dvec3(0, 1, 0)
                                                            : glm::dvec3(0, -1, 0);
        const glm::dvec3 n = placement_rotation(p) * axis;
        EXPECT_NEAR(n.y, 1.0, 1e-12) << forward_axis_name(a);
    }
}

}  // namespace
