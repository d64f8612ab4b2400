#pragma once
// The flythrough's drawing on Vulkan: a render pass into an RGBA8 colour target (already
// exposed and display-encoded by the shaders) with a reversed-Z depth buffer, the terrain's
// CDLOD patches (fly_terrain.*, one push-constant block per patch), the aircraft, then the sky
// (fly_sky.*) where no terrain was drawn, and the HUD over it all (gpu/fly/hud_overlay.hpp). The window blits that target into its swapchain image; --frames copies it to memory:
// the same pixels either way.
//
// One frame in flight: record() and the host-side updates happen while the device is idle
// (the caller waits for each frame's fence), so the frame and radiance buffers are plain
// mapped memory.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "core/fly/cdlod_tree.hpp"
#include "gpu/buffer.hpp"
#include "gpu/command.hpp"
#include "gpu/context.hpp"
#include "gpu/descriptors.hpp"
#include "gpu/fly/gpu_image.hpp"
#include "gpu/fly/hud_overlay.hpp"
#include "gpu/pipeline.hpp"

namespace ts::gpu {

// The Frame block of gpu/fly/fly_frame.glsl, field by field (std430: mat4 then vec4s).
struct FlyFrameUniforms {
    glm::mat4 view_projection{1.0f};
    glm::vec4 eye{0.0f};  // xyz: the eye (grid-frame metres), w: the sun's angular radius (rad)
    glm::vec4 grid{0.0f};
    glm::vec4 sun_direction{0.0f};
    glm::vec4 sun_radiance{0.0f};
    glm::vec4 camera_right{0.0f};
    glm::vec4 camera_up{0.0f};
    glm::vec4 camera_forward{0.0f};
    glm::vec4 sky_table{0.0f};
    glm::vec4 sky_sh[16]{};
    glm::vec4 aircraft_light{1.0f, 0.0f, 0.0f, 0.0f};
    // The aircraft's shadows (fly_frame.glsl): its spheres' bound, eye-relative centre and
    // radius (radius 0: no shadows), and the hierarchy's node count, the sky footprint's radius (m), the
    // sun's angular radius (rad), 1 for its self-shadow.
    glm::vec4 aircraft_bound{0.0f};
    glm::vec4 aircraft_shadow{0.0f};
    // x: the share of the bound's sky cover its spheres keep far from it, y: the bound's sky
    // cover above which the spheres are summed one by one (FlySettings::aircraft_sky_detail).
    glm::vec4 aircraft_sky{0.0f};
    // The overview's width and height, level-0 texels per overview texel, the CDLOD levels
    // drawn from detail tiles (fly_frame.glsl).
    glm::vec4 overview{0.0f};
};

struct PatchPush;

struct FlyTerrain {
    int width = 0, height = 0;          // level-0 texels
    std::span<const float> rows;        // per level-0 row: dx_m, north_m
    // Every overview_scale-th level-0 texel, [row][col], no voids: the whole grid (scale 1) for
    // a DEM in memory, the points of a streamed one (core/fly/terrain_overview.hpp).
    int overview_width = 0, overview_height = 0, overview_scale = 1;
    std::span<const float> heights;
    int patch_quads = 16;
    // A streamed DEM's detail tiles (core/fly/detail_tile_cache.hpp): slots and samples a side,
    // and the CDLOD levels they draw (those below the overview's).
    int atlas_slots = 0, atlas_samples = 0, detail_levels = 0;
};

class FlyRenderer {
public:
    FlyRenderer(const Context& context, const FlyTerrain& terrain, int width, int height);
    ~FlyRenderer();

    int width() const { return width_; }
    int height() const { return height_; }
    void resize(int width, int height);  // the device must be idle

    // A detail tile into atlas slot `slot`: samples_x x samples_y heights, radiance (2 words a
    // sample) and sun light (4 words), as set_radiance / set_sun_radiance, rows of samples_x.
    void set_tile(int slot, int samples_x, int samples_y, std::span<const float> heights,
                  std::span<const std::uint32_t> radiance, std::span<const std::uint32_t> sun);

    // Per-texel radiance less the sun's diffuse term, 2 words per texel (core/fly/radiance_pack.hpp).
    void set_radiance(std::span<const std::uint32_t> packed);
    // That term's parts (render::split_texel_sun), 4 words per texel (fly::pack_sun_light): the
    // fragments shade the sun from them, and an aircraft's shadow takes it away.
    void set_sun_radiance(std::span<const std::uint32_t> packed);
    // Sky radiance table, [elevation][azimuth] rgb_.
    void set_sky(std::span<const glm::vec4> table);
    // The aircraft's triangles: 3 vertices each, 3 vec4 per vertex (position, normal, colour),
    // in its model frame (metres). Empty: no aircraft.
    void set_aircraft(std::span<const glm::vec4> vertices);
    // Where the aircraft is this frame: model -> eye-relative metres; `draw` false skips it
    // (no mesh, or the cockpit view from inside it).
    void set_aircraft_transform(const glm::mat4& model_to_eye_relative, bool draw);
    // The aircraft's sphere hierarchy this frame, depth-first (blockers::FlatSphereNode): per
    // node its bound (eye-relative centre, radius; metres) and (skip index, 1 for a leaf, 0, 0).
    void set_aircraft_spheres(std::span<const glm::vec4> nodes);

    // The HUD drawn last, over everything, its top-left corner at pixel (x, y); an empty image
    // (or hide_hud) draws none. Copied to the device at the next record() only.
    void set_hud(const fly::HudImage& image, int x, int y) { hud_.set(image, x, y); }
    void hide_hud() { hud_.hide(); }

    // Records one frame into `cmd` (begun by the caller): the render pass, leaving the colour
    // target in TRANSFER_SRC_OPTIMAL for a blit or a copy.
    void record(VkCommandBuffer cmd, const FlyFrameUniforms& frame, const std::vector<fly::CdlodPatch>& patches);
    VkImage color_image() const { return color_.get(); }

    // Offscreen: record, copy the target to memory, submit and wait; RGBA8, rows top down.
    // With `depth`: the depth buffer too (reversed Z: 0 where no terrain was drawn).
    void render_to_memory(const FlyFrameUniforms& frame, const std::vector<fly::CdlodPatch>& patches,
                          std::vector<std::uint8_t>& rgba, std::vector<float>* depth = nullptr);

    const Context& context() const { return context_; }

private:
    void create_targets();
    PatchPush patch_push(const fly::CdlodPatch& p) const;
    void write_descriptors();

    const Context& context_;
    int grid_width_ = 0, grid_height_ = 0, patch_quads_ = 16;
    int overview_texels_ = 0, overview_width_ = 0, overview_height_ = 0, overview_scale_ = 1, detail_levels_ = 0;
    int atlas_samples_ = 0, atlas_slots_ = 0;
    int width_ = 0, height_ = 0;
    std::uint32_t quadrant_indices_ = 0;
    // Heights, radiance and its sun part: the overview's texels, then the atlas's slots.
    Buffer heights_, rows_, indices_, frame_, radiance_, sun_radiance_, sky_, spheres_;
    DescriptorSetLayout set_layout_;
    DescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    PipelineLayout sky_layout_, terrain_layout_, aircraft_layout_;
    DeviceHandle<VkRenderPass> render_pass_;
    DeviceHandle<VkPipeline> sky_pipeline_, terrain_pipeline_, terrain_fade_pipeline_, aircraft_pipeline_;
    Buffer aircraft_;
    std::uint32_t aircraft_vertices_ = 0;
    glm::mat4 aircraft_transform_{1.0f};
    bool draw_aircraft_ = false;
    GpuImage color_, depth_;
    DeviceHandle<VkFramebuffer> framebuffer_;
    Buffer readback_, depth_readback_;
    HudOverlay hud_;
    CommandPool command_pool_;
    CommandBuffer commands_;
    Fence fence_;
    bool color_written_ = false;
};

// The index buffer of an N x N patch: quadrant by quadrant (NW, NE, SW, SE), each quad two
// triangles split along its (0,0)-(1,1) diagonal (core/fly/cdlod_tree.hpp's mesh_error_m).
std::vector<std::uint32_t> patch_indices(int quads);

}  // namespace ts::gpu
