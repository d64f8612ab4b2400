#include "core/visibility/visibility_backend.hpp"

#include <algorithm>

#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"
#include "core/visibility/blocker_log_sh.hpp"
#include "core/visibility/earth_curvature.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/visibility_products.hpp"
#include "core/util/stopwatch.hpp"

namespace ts::visibility {
namespace {

const std::string kCpu = "cpu";

class CpuVisibilityBackend final : public VisibilityBackend {
public:
    std::string name() const override { return kCpu; }
    VisibilityResult compute(const terrain::HeightGrid& grid, const VisibilityRequest& request) override {
        check_request(request);
        VisibilityResult result;
        const Stopwatch t0;
        result.horizons = compute_horizons(grid, request.horizon);
        result.stages.push_back({"horizons (" + std::string(method_name(request.horizon.method)) + ")", kCpu,
                                 t0.seconds()});
        complete_on_cpu(grid, request, result);
        return result;
    }
};

}  // namespace

const std::string& VisibilityResult::path() const { return stages.empty() ? kCpu : stages.front().path; }

void check_request(const VisibilityRequest& request) {
    if (request.horizon.directions < 1 || request.horizon.directions > 4096)
        throw QuantityError(Quantity::directions, "", "must be between 1 and 4096, got " + std::to_string(request.horizon.directions));
    if (request.log_sh && request.horizon.directions < 4)
        throw QuantityError(Quantity::directions, "", "log-SH visibility needs at least 4, got " +
                                                                  std::to_string(request.horizon.directions));
}

void complete_on_cpu(const terrain::HeightGrid& grid, const VisibilityRequest& request, VisibilityResult& result) {
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
    const Stopwatch t0;
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
    if (!what.empty()) result.stages.push_back({what.substr(2), kCpu, t0.seconds()});

    if (request.log_sh && request.blockers && !request.blockers->empty()) {
        const Stopwatch t1;
        if (request.keep_terrain_log_sh) {
            result.terrain_log_sh.resize(result.log_sh.size());
            std::copy(result.log_sh.begin(), result.log_sh.end(), result.terrain_log_sh.begin());
        }
        const ReceiverWindow& w = request.horizon.window;
        const ReceiverWindow resolved{w.col0, w.row0, set.width, set.height};
        const BlockerStageStats st =
            add_blocker_log_sh(grid, resolved, *request.blockers,
                               curvature_factor(request.horizon.curvature), threads, result.log_sh.data());
        result.stages.push_back({"sphere blockers (" + std::to_string(request.blockers->sphere_count()) +
                                     " spheres, " + std::to_string(st.texels_changed) + " texels, " +
                                     std::to_string(st.sphere_texel_pairs) + " sphere-texel pairs)",
                                 kCpu, t1.seconds()});
    }
}

std::unique_ptr<VisibilityBackend> make_cpu_visibility_backend() { return std::make_unique<CpuVisibilityBackend>(); }

}  // namespace ts::visibility
