#pragma once
// For tests: the view-independent state, one view's shading and a frame renderer over them, as
// a Scene holds them (core/render/render_scene.hpp), built from a grid and its materials.
#include <memory>

#include "core/render/frame_renderer.hpp"

namespace ts::render::testing {

struct FrameStack {
    std::unique_ptr<ShadingState> state;
    ViewShading view;
    std::unique_ptr<FrameRenderer> frame;
    FrameStack(const terrain::HeightGrid& grid, MaterialRaster materials, NormalField normals,
               const ViewDirections& directions, const RendererOptions& options)
        : state(compute_shading_state(grid, std::move(materials), std::move(normals), options)),
          view(compute_view_shading(*state, directions)),
          frame(std::make_unique<FrameRenderer>(*state, view)) {}
    // The renderer refers to `view`: the stack stays where it was made.
    FrameStack(const FrameStack&) = delete;
    FrameStack& operator=(const FrameStack&) = delete;
    FrameRenderer* operator->() const { return frame.get(); }
};

}  // namespace ts::render::testing
