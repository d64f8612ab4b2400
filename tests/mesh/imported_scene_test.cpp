// The scene record that crosses from the importer's child process: it round-trips, and bytes
// that are not a whole, consistent record (truncated, counts beyond the bytes, indices out of
// range, a node reached twice) are one ts::InputError, never a crash or a huge allocation.
#include "core/mesh/imported_scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "core/mesh/scene_flattening.hpp"
#include "core/util/error.hpp"

namespace {
using namespace ts::mesh;

ImportedScene two_nodes() {
    ImportedScene s;
    ImportedMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    m.triangles = {0, 1, 2};
    m.material = 1;
    s.meshes.push_back(m);
    s.materials = {MeshMaterial{"a"}, MeshMaterial{"b", {0.1f, 0.2f, 0.3f, 1.0f}, "tex.png"}};
    ImportedNode root, child;
    root.children = {1};
    child.meshes = {0};
    child.transform[3] = glm::dvec4(10, 0, 0, 1);  // a translation by x = 10
    s.nodes = {root, child};
    s.header_up_axis = 2;
    return s;
}

TEST(ImportedScene, RoundTripsAndFlattensWithTheNodeTransforms) {
    const auto bytes = encode_scene(two_nodes());
    const ImportedScene s = decode_scene(bytes.data(), bytes.size(), "m.obj");
    ASSERT_EQ(s.nodes.size(), 2u);
    EXPECT_EQ(s.materials[1].base_color_texture, "tex.png");
    EXPECT_EQ(s.header_up_axis, 2);
    const TriangleMesh t = flatten_scene(s, glm::dmat4(1.0), "m.obj");
    ASSERT_EQ(t.triangle_count(), 1u);
    EXPECT_FLOAT_EQ(t.positions[1].x, 11.0f);
    EXPECT_EQ(t.material[0], 1u);
}

TEST(ImportedScene, EveryTruncationIsOneInputError) {
    const auto bytes = encode_scene(two_nodes());
    for (std::size_t n = 0; n < bytes.size(); ++n)
        EXPECT_THROW(decode_scene(bytes.data(), n, "m.obj"), ts::InputError) << n;
}

TEST(ImportedScene, ACountBeyondTheBytesIsRefusedBeforeAllocating) {
    auto bytes = encode_scene(two_nodes());
    // The node count follows the magic and the two up-axis fields.
    const std::uint64_t huge = ~std::uint64_t(0) / 2;
    std::memcpy(bytes.data() + 12, &huge, sizeof huge);
    EXPECT_THROW(decode_scene(bytes.data(), bytes.size(), "m.obj"), ts::InputError);
}

void expect_flatten_error(const ImportedScene& s, const std::string& fragment) {
    try {
        flatten_scene(s, glm::dmat4(1.0), "m.obj");
        FAIL() << "no error";
    } catch (const ts::InputError& e) {
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
}

TEST(ImportedScene, IndicesOutOfRangeAndCyclesAreErrors) {
    ImportedScene s = two_nodes();
    s.meshes[0].triangles[2] = 3;
    expect_flatten_error(s, "vertex");
    s = two_nodes();
    s.nodes[1].meshes = {5};
    expect_flatten_error(s, "mesh");
    s = two_nodes();
    s.nodes[1].children = {7};
    expect_flatten_error(s, "child");
    s = two_nodes();
    s.nodes[1].children = {0};
    expect_flatten_error(s, "reached twice");
    s = two_nodes();
    s.meshes[0].material = 9;  // out of range: the default material
    EXPECT_EQ(flatten_scene(s, glm::dmat4(1.0), "m.obj").material[0], 0u);
}

TEST(ImportedScene, NonFiniteCornersDropTheirTriangle) {
    ImportedScene s = two_nodes();
    s.meshes[0].vertices.push_back({std::nanf(""), 0, 0});
    s.meshes[0].normals.push_back({0, 0, 1});
    s.meshes[0].triangles.insert(s.meshes[0].triangles.end(), {0, 1, 3});
    EXPECT_EQ(flatten_scene(s, glm::dmat4(1.0), "m.obj").triangle_count(), 1u);
}

}  // namespace
