#include "gpu/visibility/gpu_pyramid.hpp"
#include "gpu/visibility/gpu_limits.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>

#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"
#include "core/util/stopwatch.hpp"
#include "core/visibility/bilinear_march.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/earth_curvature.hpp"
#include "core/visibility/pyramid_schedule.hpp"
#include "core/visibility/row_metrics.hpp"
#include "gpu/batch.hpp"
#include "gpu/kernel.hpp"
#include "gpu/visibility/horizon_products.hpp"

namespace ts::gpu::visibility {
namespace {

namespace vis = ts::visibility;

// Mirrors of the shaders' structs and push-constant blocks (4-byte fields, no padding).
struct LevelInfo {  // vis_pyramid_levels.glsl
    std::int32_t width, height;
    std::uint32_t offset, packed;
};
struct SampleEntry {  // vis_pyramid_horizons.comp
    float tau;
    std::int32_t level;
};
struct RowStep {
    float udx, udy, unit, pad;
};
struct LevelPush {
    std::int32_t dst;
};
struct HorizonPush {
    std::int32_t col0, row0, band_w, band_h, sample_count;
    float curvature, z_top;
};

constexpr std::uint32_t kTile = 8;             // local size of both pyramid shaders (8 x 8)
constexpr std::uint32_t kStorageBuffers = 7;   // the pyramid's bindings 0..6

// Where the levels live on the device (vis_pyramid_levels.glsl) and how level 0 is split.
struct PyramidLayout {
    int parts = 1, rows_per_part = 0;
    std::vector<LevelInfo> levels;
    VkDeviceSize level1_floats = 1, levels2_floats = 1;  // at least one: no empty buffers
    // Every level fits one storage buffer: the march reads a packed copy (LevelInfo::packed).
    bool packed = false;
    VkDeviceSize packed_floats = 0;
};

PyramidLayout plan_pyramid(const terrain::HeightGrid& grid, VkDeviceSize range, std::size_t max_height_bytes) {
    PyramidLayout p;
    const VkDeviceSize height_range = max_height_bytes > 0 ? std::min<VkDeviceSize>(range, max_height_bytes) : range;
    p.rows_per_part = int(std::min<VkDeviceSize>(VkDeviceSize(grid.height),
                                                 height_range / (VkDeviceSize(grid.width) * sizeof(float))));
    if (p.rows_per_part < 1 || (grid.height + p.rows_per_part - 1) / p.rows_per_part > kMaxHeightParts)
        throw InputError("height grid: " + std::to_string(grid.width) + "x" + std::to_string(grid.height) +
                         " needs more than " + std::to_string(kMaxHeightParts) + " GPU storage buffers of " +
                         std::to_string(height_range >> 20) + " MiB; crop it or compute on the CPU");
    p.parts = (grid.height + p.rows_per_part - 1) / p.rows_per_part;
    // terrain::HeightPyramid's sizes: halve (rounding up) down to one texel.
    int w = grid.width, h = grid.height;
    VkDeviceSize coarse = 0;  // floats of levels 2.. so far
    for (int i = 0;; ++i) {
        const VkDeviceSize texels = VkDeviceSize(w) * VkDeviceSize(h);
        p.levels.push_back({w, h, std::uint32_t(i >= 2 ? coarse : 0), std::uint32_t(p.packed_floats)});
        p.packed_floats += texels;
        if (i == 1) p.level1_floats = texels;
        if (i >= 2) coarse += texels;
        if (w == 1 && h == 1) break;
        w = (w + 1) / 2;
        h = (h + 1) / 2;
    }
    p.levels2_floats = std::max<VkDeviceSize>(1, coarse);
    p.packed = p.packed_floats * sizeof(float) <= height_range;
    if (std::max(p.level1_floats, p.levels2_floats) * sizeof(float) > range)
        throw InputError("height grid: " + std::to_string(grid.width) + "x" + std::to_string(grid.height) +
                         ": its pyramid's level 1 exceeds one GPU storage buffer of " + std::to_string(range >> 20) +
                         " MiB; crop it or compute on the CPU");
    return p;
}

// The pyramid's buffers, filled by the commands record_pyramid puts in a batch.
struct DevicePyramid {
    std::vector<Buffer> parts;
    Buffer level1, levels2, info;
    Buffer packed;  // every level one after the other, if PyramidLayout::packed (else empty)
    const Buffer& part(int i) const { return i < int(parts.size()) ? parts[std::size_t(i)] : parts[0]; }
};

Kernel level_kernel(const Context& context, const PyramidLayout& p) {
    return Kernel(context, "vis_pyramid_level",
                  {.storage_buffers = kStorageBuffers,
                   .push_constant_bytes = sizeof(LevelPush),
                   .specialization = {std::uint32_t(p.parts), std::uint32_t(p.rows_per_part)}});
}

DevicePyramid record_pyramid(const Context& context, Batch& batch, const terrain::HeightGrid& grid,
                             const PyramidLayout& p, const Kernel& level) {
    DevicePyramid d;
    for (int i = 0; i < p.parts; ++i) {
        const std::size_t first = std::size_t(i) * std::size_t(p.rows_per_part) * std::size_t(grid.width);
        const std::size_t rows = std::min(std::size_t(p.rows_per_part), std::size_t(grid.height - i * p.rows_per_part));
        d.parts.push_back(batch.upload_new(grid.z.subspan(first, rows * std::size_t(grid.width))));
    }
    d.level1 = context.create_buffer(p.level1_floats * sizeof(float));
    d.levels2 = context.create_buffer(p.levels2_floats * sizeof(float));
    d.info = batch.upload_new(std::span<const LevelInfo>(p.levels));
    // Each level from the one below (the batch orders them with barriers).
    for (int l = 1; l < int(p.levels.size()); ++l)
        batch.dispatch(level, {d.parts[0], d.part(1), d.part(2), d.part(3), d.level1, d.levels2, d.info},
                       LevelPush{l},
                       groups_for(std::uint64_t(p.levels[std::size_t(l)].width),
                                  std::uint64_t(p.levels[std::size_t(l)].height), kTile, kTile));
    if (p.packed) {
        d.packed = context.create_buffer(p.packed_floats * sizeof(float));
        VkDeviceSize at = 0;
        for (const Buffer& part : d.parts) {
            batch.copy(part, d.packed, part.size(), 0, at);
            at += part.size();
        }
        for (std::size_t l = 1; l < p.levels.size(); ++l) {
            const VkDeviceSize bytes = VkDeviceSize(p.levels[l].width) * VkDeviceSize(p.levels[l].height) * sizeof(float);
            batch.copy(l == 1 ? d.level1 : d.levels2, d.packed, bytes,
                       l == 1 ? 0 : VkDeviceSize(p.levels[l].offset) * sizeof(float), at);
            at += bytes;
        }
    }
    return d;
}

void check_grid(const terrain::HeightGrid& grid) {
    if (grid.width < 1 || grid.height < 1 || grid.z.size() != std::size_t(grid.width) * std::size_t(grid.height))
        throw InputError("height grid: empty or inconsistent size");
}

}  // namespace

std::vector<std::vector<float>> pyramid_levels(const Context& context, const terrain::HeightGrid& grid,
                                               std::size_t max_height_buffer_bytes) {
    check_grid(grid);
    const PyramidLayout p = plan_pyramid(grid, context.limits().maxStorageBufferRange, max_height_buffer_bytes);
    const Kernel level = level_kernel(context, p);
    Batch batch(context);
    const DevicePyramid d = record_pyramid(context, batch, grid, p, level);
    std::vector<std::vector<float>> out(p.levels.size());
    out[0].assign(grid.z.begin(), grid.z.end());
    for (std::size_t l = 1; l < p.levels.size(); ++l) {
        out[l].resize(std::size_t(p.levels[l].width) * std::size_t(p.levels[l].height));
        batch.download(l == 1 ? d.level1 : d.levels2, std::span<float>(out[l]),
                       l == 1 ? 0 : VkDeviceSize(p.levels[l].offset) * sizeof(float));
    }
    batch.submit_and_wait();
    return out;
}

Result compute_pyramid(const Context& context, const terrain::HeightGrid& grid, const Options& options) {
    const auto& ho = options.horizon;
    check_grid(grid);
    if (ho.method != vis::HorizonMethod::pyramid)
        throw InputError("gpu pyramid horizons: asked for the " + std::string(vis::method_name(ho.method)) + " method");
    if (ho.directions < 1 || ho.directions > kMaxGpuDirections)
        throw QuantityError(Quantity::directions, "", "the GPU path takes 1 to " + std::to_string(kMaxGpuDirections) + ", got " +
                                                          std::to_string(ho.directions) + " (compute on the CPU)");
    if (options.log_sh && ho.directions < 4)
        throw QuantityError(Quantity::sh_output, "", "needs at least 4 directions, got " + std::to_string(ho.directions));
    const vis::PyramidSchedule* schedule = vis::find_pyramid_schedule(ho.pyramid_schedule);
    if (!schedule) throw QuantityError(Quantity::pyramid_schedule, "", "unknown schedule '" + ho.pyramid_schedule + "'");
    const VkDeviceSize range = context.limits().maxStorageBufferRange;
    const PyramidLayout layout = plan_pyramid(grid, range, options.max_height_buffer_bytes);

    const vis::RowMetrics metrics(grid);
    const vis::ReceiverWindow win = vis::resolve_window(grid, ho.window);
    const int directions = ho.directions;

    // The march's samples, per-row steps and azimuths: computed in double here, as the CPU does.
    std::vector<SampleEntry> samples;
    for (const auto& s : vis::pyramid_samples(schedule->samples_per_octave, int(layout.levels.size()),
                                              vis::pyramid_max_tau(grid.width, grid.height)))
        samples.push_back({float(s.tau), s.level});
    std::vector<RowStep> rows(std::size_t(grid.height));
    for (int r = 0; r < grid.height; ++r) {
        const double dx = metrics.dx(r), dy = metrics.dy(r), unit = std::min(dx, dy);
        rows[std::size_t(r)] = {float(unit / dx), float(unit / dy), float(unit), 0.0f};
    }
    std::vector<float> dirs(std::size_t(directions) * 2);
    for (int d = 0; d < directions; ++d) {
        const double phi = vis::azimuth_rad(d, directions);
        dirs[std::size_t(d) * 2] = float(std::cos(phi));
        dirs[std::size_t(d) * 2 + 1] = float(-std::sin(phi));
    }
    // Bands of receiver rows: the horizons (and log-SH) of a band within one storage buffer.
    const VkDeviceSize per_row = VkDeviceSize(win.width) * sizeof(float) * VkDeviceSize(std::max(directions, 16));
    int band_rows = int(std::min<VkDeviceSize>(VkDeviceSize(win.height), std::max<VkDeviceSize>(1, range / per_row)));
    if (options.max_band_rows > 0) band_rows = std::min(band_rows, options.max_band_rows);

    const Kernel level = level_kernel(context, layout);
    const Kernel march(context, "vis_pyramid_horizons",
                       {.storage_buffers = kStorageBuffers + 5,
                        .push_constant_bytes = sizeof(HorizonPush),
                        .specialization = {std::uint32_t(layout.parts), std::uint32_t(layout.rows_per_part),
                                           layout.packed ? 1u : 0u}});

    const Stopwatch wall;
    Batch batch(context);
    Result result;
    HorizonProducts products(context, batch, options, win.width, win.height, result);
    const Buffer sample_buffer = batch.upload_new(std::span<const SampleEntry>(samples));
    const Buffer row_buffer = batch.upload_new(std::span<const RowStep>(rows));
    const Buffer dir_buffer = batch.upload_new(std::span<const float>(dirs));
    batch.mark("upload");
    const DevicePyramid pyramid = record_pyramid(context, batch, grid, layout, level);
    batch.mark("pyramid");
    batch.submit_and_wait();
    add_stage_times(result.stages, batch);

    const float z_top = vis::highest_height(grid);
    const float curvature = float(vis::curvature_factor(ho.curvature));
    for (int band_row0 = 0; band_row0 < win.height; band_row0 += band_rows) {
        const vis::ReceiverWindow band{win.col0, win.row0 + band_row0, win.width,
                                       std::min(band_rows, win.height - band_row0)};
        const std::size_t band_texels = std::size_t(band.width) * std::size_t(band.height);
        const Buffer horizons = context.create_buffer(band_texels * std::size_t(directions) * sizeof(float));
        Groups groups = groups_for(std::uint64_t(band.width), std::uint64_t(band.height), kTile, kTile);
        groups.z = std::uint32_t(directions);
        batch.dispatch(march,
                       {pyramid.parts[0], pyramid.part(1), pyramid.part(2), pyramid.part(3), pyramid.level1,
                        pyramid.levels2, pyramid.info, sample_buffer, row_buffer, dir_buffer, horizons,
                        layout.packed ? pyramid.packed : pyramid.parts[0]},
                       HorizonPush{band.col0, band.row0, band.width, band.height, std::int32_t(samples.size()),
                                   curvature, z_top},
                       groups);
        batch.mark("horizons");

        products.finish_band(batch, horizons, band_row0, band_texels, result);
    }
    result.wall_ms = wall.milliseconds();
    return result;
}

}  // namespace ts::gpu::visibility
