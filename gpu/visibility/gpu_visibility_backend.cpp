#include "gpu/visibility/gpu_visibility_backend.hpp"
#include "gpu/visibility/gpu_limits.hpp"

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/util/stopwatch.hpp"
#include "core/visibility/blocker_log_sh.hpp"
#include "core/visibility/earth_curvature.hpp"
#include "gpu/visibility/gpu_blocker_log_sh.hpp"
#include "gpu/visibility/gpu_visibility.hpp"

namespace ts::gpu::visibility {
namespace {

namespace vis = ts::visibility;

class GpuVisibilityBackend final : public vis::VisibilityBackend {
public:
    GpuVisibilityBackend(const Context& context, const GpuVisibilityOptions& options)
        : context_(context), options_(options), cpu_(vis::make_cpu_visibility_backend()) {}

    std::string name() const override { return context_.device_info().name; }

    vis::VisibilityResult compute(const terrain::HeightGrid& grid, const vis::VisibilityRequest& request) override {
        vis::check_request(request);
        if (request.horizon.method == vis::HorizonMethod::raymarch || request.horizon.directions > kMaxGpuDirections)
            return cpu_->compute(grid, request);
        Options go;
        go.horizon = request.horizon;
        go.log_eps = request.log_eps;
        go.log_sh = request.log_sh;
        go.sky = (request.svf || request.sky_visible) && request.wedges == vis::WedgeRule::linear;
        go.max_band_rows = options_.max_band_rows;
        const Stopwatch t0;
        Result r = gpu::visibility::compute(context_, grid, go);
        vis::VisibilityResult result;
        result.horizons = std::move(r.horizons);
        result.log_sh = std::move(r.log_sh);
        if (request.svf) result.svf = std::move(r.svf);
        if (request.sky_visible) result.sky_visible = std::move(r.sky_visible);
        std::string label = "horizons (" + std::string(vis::method_name(request.horizon.method)) + ")";
        if (go.log_sh) label += ", log-SH";
        if (go.sky) label += ", svf, sky_visible";
        result.stages.push_back(
            {label, name(), t0.seconds()});
        const bool blockers_here = request.log_sh && request.blockers && !request.blockers->empty() &&
                                   vis::device_can_add_blockers(*request.blockers);
        if (!blockers_here) {
            vis::complete_on_cpu(grid, request, result);  // mesh blockers too, on the CPU
            return result;
        }
        vis::VisibilityRequest rest = request;
        rest.blockers = nullptr, rest.keep_terrain_log_sh = false;
        vis::complete_on_cpu(grid, rest, result);
        add_blockers(grid, request, result);
        return result;
    }

private:
    // The meshes' sphere log-SH on the device (blocker_log_sh.comp), into result.log_sh, as
    // complete_on_cpu adds it on the CPU without culling: the footprints' receivers gathered
    // (one entry per receiver and mesh that counts there), accumulated, scattered back.
    void add_blockers(const terrain::HeightGrid& grid, const vis::VisibilityRequest& request,
                      vis::VisibilityResult& result) const {
        const Stopwatch t;
        if (request.keep_terrain_log_sh) {
            result.terrain_log_sh.resize(result.log_sh.size());
            std::copy(result.log_sh.begin(), result.log_sh.end(), result.terrain_log_sh.begin());
        }
        const vis::ReceiverWindow& w = request.horizon.window;
        const vis::ReceiverWindow resolved{w.col0, w.row0, result.horizons.width, result.horizons.height};
        const blockers::SphereBlockers& b = *request.blockers;
        const vis::FlatBlockerReceivers rec = vis::flat_blocker_receivers(
            grid, resolved, b, vis::curvature_factor(request.horizon.curvature), request.horizon.threads);
        // Every mesh's spheres in one list, each mesh a range of it.
        std::vector<blockers::Sphere> spheres;
        std::vector<std::uint32_t> first;
        for (const blockers::PlacedSpheres& m : b.meshes) {
            first.push_back(std::uint32_t(spheres.size()));
            spheres.insert(spheres.end(), m.spheres.begin(), m.spheres.end());
        }
        std::vector<GpuBlockerEntry> entries(rec.receiver.size());
        long long pairs = 0;
        for (std::size_t e = 0; e < entries.size(); ++e) {
            const std::uint32_t k = rec.mesh[e];
            entries[e] = {rec.positions[e], rec.normals[e], first[k], std::uint32_t(b.meshes[k].spheres.size())};
            pairs += (long long)b.meshes[k].spheres.size();
        }
        const std::size_t n = rec.texels.size(), texels = result.log_sh.size() / 16;
        std::vector<float> log_sh(16 * n);
        for (std::size_t i = 0; i < 16; ++i)
            for (std::size_t k = 0; k < n; ++k) log_sh[i * n + k] = result.log_sh[i * texels + rec.texels[k]];
        if (!blocker_kernel_) blocker_kernel_ = std::make_unique<GpuBlockerLogSh>(context_);
        blocker_kernel_->add(entries, rec.receiver, n, spheres, float(b.options.log_eps), b.options.attenuation,
                             log_sh);
        for (std::size_t i = 0; i < 16; ++i)
            for (std::size_t k = 0; k < n; ++k) result.log_sh[i * texels + rec.texels[k]] = log_sh[i * n + k];
        result.stages.push_back({"sphere blockers (" + std::to_string(b.meshes.size()) + " mesh" +
                                     (b.meshes.size() == 1 ? "" : "es") + ", " + std::to_string(b.sphere_count()) +
                                     " spheres, " + std::to_string(n) + " texels, " + std::to_string(pairs) +
                                     " sphere-texel pairs)",
                                 name(), t.seconds()});
    }

    const Context& context_;
    mutable std::unique_ptr<GpuBlockerLogSh> blocker_kernel_;
    GpuVisibilityOptions options_;
    std::unique_ptr<vis::VisibilityBackend> cpu_;
};

}  // namespace

std::unique_ptr<ts::visibility::VisibilityBackend> make_gpu_visibility_backend(const Context& context,
                                                                               const GpuVisibilityOptions& options) {
    return std::make_unique<GpuVisibilityBackend>(context, options);
}

}  // namespace ts::gpu::visibility
