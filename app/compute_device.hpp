#pragma once
// Where a command computes: one choice for every command (`--device auto|cpu|vulkan|N`).
//   auto (default)  a discrete, integrated or virtual GPU when there is one; the CPU path when
//                   the only Vulkan device is a CPU implementation (lavapipe/llvmpipe), where
//                   the CPU path is the faster use of the same cores, or when there is none
//   cpu             the CPU path (also `--cpu`)
//   vulkan          the best Vulkan device, whatever its type (an error if there is none)
//   N               Vulkan device N as `terrashade devices` lists it
// `--verbose` prints the path taken and why. The backends it hands out are the two seams:
// visibility (core/visibility/visibility_backend.hpp) and transfer/shading
// (core/render/render_backend.hpp).
//
//   ComputeDevice device(args.device);   // declared before what uses its backends
//   device.apply(scene_options);         // render/relight: visibility and transfer backends
//   device.visibility().compute(grid, request);
#include <memory>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "core/render/render_backend.hpp"
#include "core/render/render_scene.hpp"
#include "core/sh/exp_method.hpp"
#include "core/visibility/visibility_backend.hpp"

namespace ts::app {

struct DeviceArgs {
    std::string device = "auto";
    bool cpu = false;  // --cpu: the same as --device cpu
    bool verbose = false;
};

// Adds --device, --cpu and --verbose to `cmd`.
void add_device_options(CLI::App& cmd, DeviceArgs& args);

// What `--device auto` would take on this machine, and why (for `terrashade devices`).
struct DeviceChoice {
    bool vulkan = false;
    std::optional<std::uint32_t> index;  // the Vulkan device (vulkan only)
    bool automatic = false;              // --device auto decided
    std::string reason;
};
// Throws ts::InputError for a bad --device value or a device that cannot be used; never for
// auto (a machine without Vulkan takes the CPU path).
DeviceChoice choose_device(const DeviceArgs& args);

class ComputeDevice {
public:
    explicit ComputeDevice(const DeviceArgs& args);
    ~ComputeDevice();
    ComputeDevice(const ComputeDevice&) = delete;
    ComputeDevice& operator=(const ComputeDevice&) = delete;

    bool on_vulkan() const { return vulkan_ != nullptr; }
    // "cpu" or the Vulkan device's name.
    std::string name() const;
    const std::string& reason() const { return choice_.reason; }

    visibility::VisibilityBackend& visibility() const { return *visibility_; }
    // The transfer/shading backend for an exponentiation: nullptr = the CPU path (the
    // renderer's own fused shading); the CPU too, with a note, for a method the GPU lacks.
    render::RenderBackend* render_backend(sh::ExpMethod method) const;
    // Sets options.renderer.visibility and .backend.
    void apply(render::SceneOptions& options) const;

private:
    struct Vulkan;  // the gpu::Context and its backends (a GPU build only)
    DeviceChoice choice_;
    bool verbose_ = false;
    std::unique_ptr<Vulkan> vulkan_;
    std::unique_ptr<visibility::VisibilityBackend> cpu_visibility_;
    visibility::VisibilityBackend* visibility_ = nullptr;  // the Vulkan one or cpu_visibility_
};

}  // namespace ts::app
