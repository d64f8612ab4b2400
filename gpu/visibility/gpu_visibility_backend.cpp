#include "gpu/visibility/gpu_visibility_backend.hpp"

#include <utility>

#include "gpu/visibility/gpu_visibility.hpp"
#include "core/util/stopwatch.hpp"

namespace ts::gpu::visibility {
namespace {

namespace vis = ts::visibility;

// Directions beyond what the device's loops allow (gpu_visibility.cpp).
constexpr int kMaxGpuDirections = 2048;

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
        vis::complete_on_cpu(grid, request, result);  // mesh blockers too, on the CPU
        return result;
    }

private:
    const Context& context_;
    GpuVisibilityOptions options_;
    std::unique_ptr<vis::VisibilityBackend> cpu_;
};

}  // namespace

std::unique_ptr<ts::visibility::VisibilityBackend> make_gpu_visibility_backend(const Context& context,
                                                                               const GpuVisibilityOptions& options) {
    return std::make_unique<GpuVisibilityBackend>(context, options);
}

}  // namespace ts::gpu::visibility
