#pragma once
// Meshes drawn into a perspective view of the terrain (docs/rendering.md, "Meshes in
// perspective views"): their placed triangles are rasterised once per camera, 2 x 2 samples a
// pixel, each sample depth-tested against the other triangles and against the terrain's hit
// along its pixel's ray (PerspectiveView::terrain_distance); every frame then only blends the
// per-receiver radiance of MeshLighting (Gouraud, perspective-correct) over the terrain's
// picture, through the same haze.
//
// Positions go from a mesh's anchor frame to the grid (anchor_frame_to_grid) and into the
// camera's frame with its row's spacing and the curvature drop the terrain gets there, so a
// mesh stands where the terrain under it is drawn. A triangle with a corner closer than
// kNearPlaneM in front of the camera (or behind it) is skipped, not clipped.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/render/mesh_lighting.hpp"
#include "core/render/perspective_view.hpp"
#include "core/light/sky_table.hpp"

namespace ts::render {

class MeshView {
public:
    static constexpr int kSamples = 2;  // per pixel side
    static constexpr double kNearPlaneM = 0.5;

    // `view` must outlive this; the meshes are only read here.
    MeshView(const terrain::HeightGrid& grid, const PerspectiveView& view, std::span<const PlacedMesh* const> meshes,
             bool curvature);

    // Pixels with at least one sample on a mesh.
    std::size_t covered_pixels() const { return covered_.size(); }
    // Samples that lost the depth test to the terrain.
    std::size_t hidden_samples() const { return hidden_; }

    // Blends the meshes over `image` (the view's composed picture): receiver_radiance[m] is mesh
    // m's MeshLighting::radiance (2 per corner: the normal's side, then the other).
    void compose(std::span<const std::vector<glm::vec3>> receiver_radiance, const light::SkyTable& sky,
                 std::vector<glm::vec3>& image) const;

private:
    struct Sample {
        std::uint32_t mesh = 0, triangle = 0;
        float b1 = 0, b2 = 0;  // perspective-correct barycentrics of corners 1 and 2
        float distance = 0;     // along the sample's ray, metres
        bool back = false;      // seen from the side opposite its normals
        bool hit = false;
    };
    struct Covered {
        std::uint32_t pixel;
        Sample samples[kSamples * kSamples];
    };
    const PerspectiveView& view_;
    std::vector<Covered> covered_;
    std::vector<std::uint32_t> corners_;  // per mesh: its corner count
    std::size_t hidden_ = 0;
};

}  // namespace ts::render
