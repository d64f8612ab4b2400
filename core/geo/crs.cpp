// Crs on PROJ. One PJ_CONTEXT per Crs, and a mutex around every transform: PROJ objects are
// not safe to share between threads, and a per-call lock is cheap next to a reprojection.
#include "core/geo/crs.hpp"

#include <cmath>
#include <mutex>

#include <proj.h>

#include "core/util/error.hpp"

namespace ts::geo {

struct Crs::Impl {
    PJ_CONTEXT* ctx = nullptr;
    PJ* crs = nullptr;             // the CRS itself
    PJ* to_wgs84 = nullptr;        // CRS -> EPSG:4326, lon first (null for WGS84 itself)
    std::string definition;
    std::string name;
    std::optional<int> epsg;
    bool geographic = false;
    mutable std::mutex mutex;

    ~Impl() {
        if (to_wgs84) proj_destroy(to_wgs84);
        if (crs) proj_destroy(crs);
        if (ctx) proj_context_destroy(ctx);
    }
};

namespace {

bool is_geographic_type(PJ_TYPE t) {
    return t == PJ_TYPE_GEOGRAPHIC_2D_CRS || t == PJ_TYPE_GEOGRAPHIC_3D_CRS || t == PJ_TYPE_GEOGRAPHIC_CRS;
}

bool is_crs_type(PJ_TYPE t) {
    switch (t) {
        case PJ_TYPE_GEOGRAPHIC_2D_CRS: case PJ_TYPE_GEOGRAPHIC_3D_CRS: case PJ_TYPE_GEOGRAPHIC_CRS:
        case PJ_TYPE_PROJECTED_CRS: case PJ_TYPE_BOUND_CRS: case PJ_TYPE_COMPOUND_CRS:
        case PJ_TYPE_GEOCENTRIC_CRS: case PJ_TYPE_OTHER_CRS:
            return true;
        default:
            return false;
    }
}

// EPSG code of `crs`: its own identifier, else PROJ's identification when exactly one EPSG
// entry is equivalent (confidence >= 70: same datum and coordinate system, names aside), so
// "+proj=utm +zone=33 +datum=WGS84" is EPSG:32633 in all but name.
std::optional<int> find_epsg(PJ_CONTEXT* ctx, PJ* crs) {
    const char* auth = proj_get_id_auth_name(crs, 0);
    const char* code = proj_get_id_code(crs, 0);
    if (auth && code && std::string(auth) == "EPSG") return std::stoi(code);
    int* confidence = nullptr;
    PJ_OBJ_LIST* candidates = proj_identify(ctx, crs, "EPSG", nullptr, &confidence);
    std::optional<int> found;
    if (candidates) {
        const int n = proj_list_get_count(candidates);
        const bool unique = n == 1 || (n > 1 && confidence[1] < confidence[0]);
        if (n >= 1 && confidence && confidence[0] >= 70 && unique) {
            PJ* best = proj_list_get(ctx, candidates, 0);
            if (const char* c = proj_get_id_code(best, 0)) found = std::stoi(c);
            proj_destroy(best);
        }
        proj_list_destroy(candidates);
    }
    if (confidence) proj_int_list_destroy(confidence);
    return found;
}

}  // namespace

Crs::Crs(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Crs::~Crs() = default;

std::shared_ptr<const Crs> Crs::from_definition(const std::string& definition) {
    auto impl = std::make_unique<Impl>();
    impl->definition = definition;
    impl->ctx = proj_context_create();
    // Errors reach the user as one InputError line, never as PROJ's log: no level, no sink.
    proj_log_level(impl->ctx, PJ_LOG_NONE);
    proj_log_func(impl->ctx, nullptr, [](void*, int, const char*) {});
    impl->crs = proj_create(impl->ctx, definition.c_str());
    if (!impl->crs || !is_crs_type(proj_get_type(impl->crs)))
        throw InputError("unknown coordinate reference system '" + definition + "'");
    if (const char* n = proj_get_name(impl->crs)) impl->name = n;
    impl->epsg = find_epsg(impl->ctx, impl->crs);
    PJ_TYPE type = proj_get_type(impl->crs);
    if (type == PJ_TYPE_BOUND_CRS) {
        PJ* base = proj_get_source_crs(impl->ctx, impl->crs);
        if (base) {
            type = proj_get_type(base);
            proj_destroy(base);
        }
    }
    impl->geographic = is_geographic_type(type);

    if (impl->epsg != 4326) {
        PJ* raw = proj_create_crs_to_crs(impl->ctx, definition.c_str(), "EPSG:4326", nullptr);
        if (!raw) throw InputError("no transformation from '" + definition + "' to WGS 84");
        impl->to_wgs84 = proj_normalize_for_visualization(impl->ctx, raw);
        proj_destroy(raw);
        if (!impl->to_wgs84) throw InputError("no transformation from '" + definition + "' to WGS 84");
    }
    return std::shared_ptr<const Crs>(new Crs(std::move(impl)));
}

std::shared_ptr<const Crs> Crs::from_definition(const std::string& definition, const std::string& fallback_name) {
    auto crs = from_definition(definition);
    if ((crs->impl_->name.empty() || crs->impl_->name == "unknown") && !fallback_name.empty())
        crs->impl_->name = fallback_name;  // not yet shared with anyone: still ours to name
    return crs;
}

std::shared_ptr<const Crs> Crs::from_epsg(int code) {
    return from_definition("EPSG:" + std::to_string(code));
}

std::optional<int> Crs::epsg() const { return impl_->epsg; }
const std::string& Crs::name() const { return impl_->name; }
const std::string& Crs::definition() const { return impl_->definition; }
bool Crs::is_geographic() const { return impl_->geographic; }

glm::dvec2 Crs::to_lonlat(glm::dvec2 xy) const {
    if (!impl_->to_wgs84) return xy;
    std::lock_guard lock(impl_->mutex);
    PJ_COORD c = proj_coord(xy.x, xy.y, 0, 0);
    PJ_COORD r = proj_trans(impl_->to_wgs84, PJ_FWD, c);
    return {r.xy.x, r.xy.y};
}

glm::dvec2 Crs::from_lonlat(glm::dvec2 lonlat) const {
    if (!impl_->to_wgs84) return lonlat;
    std::lock_guard lock(impl_->mutex);
    PJ_COORD c = proj_coord(lonlat.x, lonlat.y, 0, 0);
    PJ_COORD r = proj_trans(impl_->to_wgs84, PJ_INV, c);
    return {r.xy.x, r.xy.y};
}

bool Crs::same_as(const Crs& other) const {
    if (this == &other) return true;
    if (epsg() && other.epsg()) return *epsg() == *other.epsg();
    return proj_is_equivalent_to_with_ctx(impl_->ctx, impl_->crs, other.impl_->crs, PJ_COMP_EQUIVALENT) != 0;
}

std::string Crs::to_proj_string() const {
    std::lock_guard lock(impl_->mutex);
    const char* s = proj_as_proj_string(impl_->ctx, impl_->crs, PJ_PROJ_5, nullptr);
    return s ? std::string(s) : std::string();
}

std::string Crs::to_wkt() const {
    std::lock_guard lock(impl_->mutex);
    const char* s = proj_as_wkt(impl_->ctx, impl_->crs, PJ_WKT1_GDAL, nullptr);
    return s ? std::string(s) : std::string();
}

std::optional<LinearUnit> vertical_crs_unit(int code) {
    PJ_CONTEXT* ctx = proj_context_create();
    proj_log_level(ctx, PJ_LOG_NONE);
    std::optional<LinearUnit> out;
    const std::string text = std::to_string(code);
    if (PJ* crs = proj_create_from_database(ctx, "EPSG", text.c_str(), PJ_CATEGORY_CRS, 0, nullptr)) {
        if (proj_get_type(crs) == PJ_TYPE_VERTICAL_CRS)
            if (PJ* cs = proj_crs_get_coordinate_system(ctx, crs)) {
                const char* name = nullptr;
                double factor = 0;
                if (proj_cs_get_axis_info(ctx, cs, 0, nullptr, nullptr, nullptr, &factor, &name, nullptr, nullptr) &&
                    factor > 0)
                    out = LinearUnit{name ? name : "", factor};
                proj_destroy(cs);
            }
        proj_destroy(crs);
    }
    proj_context_destroy(ctx);
    return out;
}

std::optional<LinearUnit> linear_unit(int code) {
    PJ_CONTEXT* ctx = proj_context_create();
    proj_log_level(ctx, PJ_LOG_NONE);
    std::optional<LinearUnit> out;
    const char* name = nullptr;
    const char* category = nullptr;
    double factor = 0;
    const std::string text = std::to_string(code);
    if (proj_uom_get_info_from_database(ctx, "EPSG", text.c_str(), &name, &factor, &category) && category &&
        std::string(category) == "linear" && factor > 0)
        out = LinearUnit{name ? name : "", factor};
    proj_context_destroy(ctx);
    return out;
}

}  // namespace ts::geo
