#pragma once
// Where per-texel visibility is computed: one interface, whatever runs it. The CPU
// implementation (make_cpu_visibility_backend) is the reference; gpu/visibility provides the
// Vulkan one (gpu/visibility/gpu_visibility_backend.hpp). Commands choose a backend
// (app/compute_device.hpp) and call compute(); they never combine stages themselves.
//
//   auto backend = visibility::make_cpu_visibility_backend();
//   VisibilityRequest request{.horizon = {.directions = 32}, .log_sh = true, .svf = true};
//   VisibilityResult r = backend->compute(grid, request);   // r.horizons, r.log_sh, r.svf
//
// A backend computes what it can and leaves the rest to complete_on_cpu(), so every request is
// answered whole by every backend: what differs is only where each product was computed
// (VisibilityResult::stages says).
#include <memory>
#include <string>
#include <vector>

#include "core/blockers/placed_spheres.hpp"
#include "core/terrain/height_grid.hpp"
#include "core/util/uninitialised_vector.hpp"
#include "core/visibility/horizon_options.hpp"
#include "core/visibility/horizon_set.hpp"
#include "core/visibility/horizon_sh.hpp"
#include "core/visibility/sky_integrals.hpp"

namespace ts::visibility {

// What to compute for the receivers of `horizon.window` (the whole grid by default). Horizons
// are always computed (every product derives from them).
struct VisibilityRequest {
    HorizonOptions horizon;
    bool log_sh = false;       // 16 log-SH coefficients per texel (needs D >= 4)
    bool svf = false;          // sky view factor
    bool sky_visible = false;  // visible fraction of the upper hemisphere
    WedgeRule wedges = WedgeRule::linear;  // how svf and sky_visible integrate across azimuth
    float log_eps = kDefaultVisibilityLogEps;
    // Mesh blockers over the grid (must outlive the call); their sphere log-SH joins the
    // terrain's in the log-SH product (blocker_log_sh.hpp), inside each mesh's footprint. svf and
    // sky_visible stay the terrain's. nullptr or empty: none.
    const blockers::SphereBlockers* blockers = nullptr;
    // With blockers: also return the log-SH before the blockers were added (terrain_log_sh),
    // for consumers that bound or redo the blockers' part (core/render/shading_state.hpp).
    bool keep_terrain_log_sh = false;
};

// One stage of a computation and where it ran, for logs and benchmarks.
struct VisibilityStage {
    std::string label;  // "horizons", "log-SH, svf", ...
    std::string path;   // "cpu" or the Vulkan device's name
    double seconds = 0;
};

// Layouts: horizons as compute_horizons; log_sh [coefficient][texel] as log_sh_raster; svf and
// sky_visible one float per texel. A product not requested is empty. NaN for void receivers.
struct VisibilityResult {
    HorizonSet horizons;
    UninitialisedVector<float> log_sh, svf, sky_visible;
    // The terrain's own log-SH when the request had blockers and keep_terrain_log_sh (else empty).
    UninitialisedVector<float> terrain_log_sh;
    std::vector<VisibilityStage> stages;
    // Where the horizons were computed (the first stage's path).
    const std::string& path() const;
};

class VisibilityBackend {
public:
    virtual ~VisibilityBackend() = default;
    // "cpu" or the Vulkan device's name.
    virtual std::string name() const = 0;
    // Throws ts::InputError for a bad request (empty grid, bad window, D < 4 with log_sh, ...).
    virtual VisibilityResult compute(const terrain::HeightGrid& grid, const VisibilityRequest& request) = 0;
};

// The CPU path: compute_horizons, then every product in one pass (visibility_products).
std::unique_ptr<VisibilityBackend> make_cpu_visibility_backend();

// Computes on the CPU the products `request` asks for that `result` does not hold yet (from
// result.horizons), appending a stage for them, then adds the mesh blockers' log-SH (a stage
// of its own, "sphere blockers"). Any backend ends with it: it is the one place blockers and
// the height field meet.
void complete_on_cpu(const terrain::HeightGrid& grid, const VisibilityRequest& request, VisibilityResult& result);

// Checks what can be checked before any work (InputError).
void check_request(const VisibilityRequest& request);

}  // namespace ts::visibility
