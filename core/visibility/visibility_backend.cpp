#include "core/visibility/visibility_backend.hpp"

#include <algorithm>
#include <chrono>

#include "core/util/error.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/visibility_products.hpp"

namespace ts::visibility {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

const std::string kCpu = "cpu";

class CpuVisibilityBackend final : public VisibilityBackend {
public:
    std::string name() const override { return kCpu; }
    VisibilityResult compute(const terrain::HeightGrid& grid, const VisibilityRequest& request) override {
        check_request(request);
        VisibilityResult result;
        const auto t0 = std::chrono::steady_clock::now();
        result.horizons = compute_horizons(grid, request.horizon);
        result.stages.push_back({"horizons (" + std::string(method_name(request.horizon.method)) + ")", kCpu,
                                 seconds_since(t0)});
        complete_on_cpu(request, result);
        return result;
    }
};

}  // namespace

const std::string& VisibilityResult::path() const { return stages.empty() ? kCpu : stages.front().path; }

void check_request(const VisibilityRequest& request) {
    if (request.horizon.directions < 1 || request.horizon.directions > 4096)
        throw InputError("--directions: must be between 1 and 4096, got " + std::to_string(request.horizon.directions));
    if (request.log_sh && request.horizon.directions < 4)
        throw InputError("log-SH visibility needs at least 4 --directions, got " +
                         std::to_string(request.horizon.directions));
}

void complete_on_cpu(const VisibilityRequest& request, VisibilityResult& result) {
    const HorizonSet& set = result.horizons;
    const int threads = request.horizon.threads;
    const bool linear = request.wedges == WedgeRule::linear;
    // The one-pass products (linear wedges) for whatever is missing.
    ProductRequest pass;
    pass.log_sh = request.log_sh && result.log_sh.empty();
    pass.svf = request.svf && linear && result.svf.empty();
    pass.sky_visible = request.sky_visible && linear && result.sky_visible.empty();
    pass.log_eps = request.log_eps;
    pass.threads = threads;
    std::string what;
    const auto t0 = std::chrono::steady_clock::now();
    if (pass.log_sh || pass.svf || pass.sky_visible) {
        VisibilityProducts p = visibility_products(set, pass);
        if (pass.log_sh) result.log_sh = std::move(p.log_sh), what += ", log-SH";
        if (pass.svf) result.svf = std::move(p.svf), what += ", svf";
        if (pass.sky_visible) result.sky_visible = std::move(p.sky_visible), what += ", sky_visible";
    }
    // Constant wedges (as GIS tools integrate) are not in the one-pass products: per texel.
    auto assign = [](UninitialisedVector<float>& to, const std::vector<float>& from) {
        to.resize(from.size());
        std::copy(from.begin(), from.end(), to.begin());
    };
    if (request.svf && result.svf.empty()) {
        assign(result.svf, svf_raster(set, request.wedges, threads));
        what += ", svf (constant wedges)";
    }
    if (request.sky_visible && result.sky_visible.empty()) {
        assign(result.sky_visible, sky_visible_raster(set, request.wedges, threads));
        what += ", sky_visible (constant wedges)";
    }
    if (!what.empty()) result.stages.push_back({what.substr(2), kCpu, seconds_since(t0)});
}

std::unique_ptr<VisibilityBackend> make_cpu_visibility_backend() { return std::make_unique<CpuVisibilityBackend>(); }

}  // namespace ts::visibility
