#include "core/fly/detail_tile_cache.hpp"

#include <algorithm>
#include <cmath>

#include "core/fly/radiance_pack.hpp"
#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"

namespace ts::fly {

DetailTileCache::DetailTileCache(const dem::DemSource& source, const TerrainOverview& overview,
                                 const visibility::FarField& far, const GridFrame& frame, int patch_quads,
                                 const DetailCacheOptions& options)
    : source_(source), overview_(overview), far_(far), frame_(frame),
      layout_(detail_tile_layout(overview, patch_quads)), options_(options) {
    // The palette fitted once on the overview, not by every tile it builds (DetailTile fits
    // only a palette that is not fitted yet).
    options_.shading.colors = render::fit_colors(options_.shading.colors, overview.points);
    tile_bytes_ = detail_tile_bytes(layout_.tile_texels, options.shading.halo);
    const std::size_t tiles = std::size_t(layout_.tiles_x) * std::size_t(layout_.tiles_y);
    slots_ = int(std::min(options.budget_bytes / tile_bytes_, tiles));
    // Four tiles: the corner of four tiles under the eye (or every tile of a smaller DEM).
    const int needed = int(std::min<std::size_t>(4, tiles));
    if (slots_ < needed)
        throw QuantityError(Quantity::memory_budget, "", "the detail tiles' share (" + std::to_string(options.budget_bytes >> 20) +
                         " MB after the overview and far field) holds fewer than " + std::to_string(needed) +
                         " tiles of " + std::to_string(tile_bytes_ >> 20) + " MB; give it " +
                         std::to_string(((std::size_t(needed) * tile_bytes_ - options.budget_bytes) >> 20) + 1) + " MB more");
    for (int s = slots_ - 1; s >= 0; --s) free_slots_.push_back(s);
    worker_ = std::thread([this] { worker_loop(); });
}

DetailTileCache::~DetailTileCache() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    worker_.join();
}

std::unique_ptr<DetailTile> DetailTileCache::build(DetailTileKey key, int threads) const {
    DetailShadingOptions o = options_.shading;
    o.threads = threads;
    return std::make_unique<DetailTile>(key, layout_, source_, overview_, far_, o);
}

void DetailTileCache::worker_loop() {
    for (;;) {
        DetailTileKey key;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || !queue_.empty(); });
            if (stop_) return;
            key = queue_.back().second;
            queue_.pop_back();
            building_.insert(key);
        }
        std::unique_ptr<DetailTile> tile;
        try {
            tile = build(key, options_.worker_threads);
        } catch (const std::exception&) {
            // A tile that cannot be read (a file changed under the flight) stays coarse and is
            // not asked for again; the overview still draws its terrain.
        }
        std::lock_guard<std::mutex> lock(mutex_);
        building_.erase(key);
        if (tile) done_.push_back(std::move(tile));
        else failed_.insert(key);
    }
}

bool DetailTileCache::node_z_range(int level, int ix, int iy, glm::vec2& z) {
    const auto it = resident_.find(tile_of_node(layout_, level, ix, iy));
    if (it == resident_.end()) return false;
    it->second.last_used = frame_count_;
    z = it->second.tile->node_z(level, ix, iy);
    return true;
}

void DetailTileCache::request(int level, int ix, int iy, double distance_m) {
    const DetailTileKey key = tile_of_node(layout_, level, ix, iy);
    auto [it, fresh] = wanted_.emplace(key, distance_m);
    if (!fresh) it->second = std::min(it->second, distance_m);
}

int DetailTileCache::slot_of_node(int level, int ix, int iy) const {
    const auto it = resident_.find(tile_of_node(layout_, level, ix, iy));
    return it == resident_.end() ? -1 : it->second.slot;
}

const DetailTile* DetailTileCache::tile_at(double col, double row) const {
    const int T = layout_.tile_texels;
    const int tx = std::clamp(int(std::floor(col / T)), 0, layout_.tiles_x - 1);
    const int ty = std::clamp(int(std::floor(row / T)), 0, layout_.tiles_y - 1);
    const auto it = resident_.find({tx, ty});
    return it == resident_.end() ? nullptr : it->second.tile.get();
}

std::size_t DetailTileCache::pending() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return queue_.size() + building_.size() + done_.size();
}

void DetailTileCache::lit_upload(Resident& r) {
    r.sun_generation = sun_generation_;
    DetailSlotData d;
    d.slot = r.slot;
    d.col0 = r.tile->col0(), d.row0 = r.tile->row0();
    d.samples_x = r.tile->samples_x(), d.samples_y = r.tile->samples_y();
    d.heights = &r.tile->heights();
    r.tile->light(sun_, d.radiance, d.sun);
    // A slot listed twice keeps its last contents only.
    std::erase_if(uploads_, [&](const DetailSlotData& u) { return u.slot == d.slot; });
    uploads_.push_back(std::move(d));
}

void DetailTileCache::set_sun(const render::SunState& sun) {
    sun_ = sun;
    ++sun_generation_;
    for (auto& [key, r] : resident_) lit_upload(r);
}

void DetailTileCache::admit(std::unique_ptr<DetailTile> tile) {
    const DetailTileKey key = tile->key();
    if (resident_.count(key)) return;
    if (free_slots_.empty()) {
        // The least recently used tile that this frame did not use.
        auto victim = resident_.end();
        for (auto it = resident_.begin(); it != resident_.end(); ++it)
            if (it->second.last_used < frame_count_ && (victim == resident_.end() || it->second.last_used < victim->second.last_used))
                victim = it;
        if (victim == resident_.end()) return;  // every slot in use this frame: the budget is full
        free_slots_.push_back(victim->second.slot);
        std::erase_if(uploads_, [&](const DetailSlotData& u) { return u.slot == victim->second.slot; });
        resident_.erase(victim);
    }
    Resident r;
    r.tile = std::move(tile);
    r.slot = free_slots_.back();
    free_slots_.pop_back();
    r.last_used = frame_count_;
    ++loaded_;
    auto& placed = resident_.emplace(key, std::move(r)).first->second;
    lit_upload(placed);
    peak_bytes_ = std::max(peak_bytes_, resident_bytes());
}

void DetailTileCache::update(const glm::dvec3& eye) {
    // Prefetch: tiles whose footprint comes within the radius (horizontally).
    if (options_.prefetch_m > 0) {
        const glm::dvec2 g = frame_.to_grid(eye.x, eye.y);
        const int row = std::clamp(int(g.y), 0, layout_.height - 1);
        const double texel = std::min(frame_.row_dx_m()[std::size_t(row)], std::abs(frame_.north_at(row + 1) - frame_.north_at(row)));
        const double reach = options_.prefetch_m / std::max(texel, 1e-6);
        const int T = layout_.tile_texels;
        const int tx0 = std::max(0, int(std::floor((g.x - reach) / T))), tx1 = std::min(layout_.tiles_x - 1, int(std::floor((g.x + reach) / T)));
        const int ty0 = std::max(0, int(std::floor((g.y - reach) / T))), ty1 = std::min(layout_.tiles_y - 1, int(std::floor((g.y + reach) / T)));
        for (int ty = ty0; ty <= ty1; ++ty)
            for (int tx = tx0; tx <= tx1; ++tx) {
                const double dc = std::max({0.0, tx * T - g.x, g.x - (tx + 1) * T});
                const double dr = std::max({0.0, ty * T - g.y, g.y - (ty + 1) * T});
                const double d = std::hypot(dc, dr) * texel;
                if (d > options_.prefetch_m) continue;
                const auto it = resident_.find({tx, ty});
                if (it != resident_.end()) {
                    it->second.last_used = frame_count_;
                    continue;
                }
                auto [w, fresh] = wanted_.emplace(DetailTileKey{tx, ty}, d);
                if (!fresh) w->second = std::min(w->second, d);
            }
    }
    // The finished tiles first: a tile waiting to be admitted is not queued again.
    std::vector<std::unique_ptr<DetailTile>> done;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        done.swap(done_);
    }
    for (auto& t : done) admit(std::move(t));
    bool queued = false;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        queue_.clear();
        // The nearest wanted tiles the free and evictable slots can take, nearest last.
        for (const auto& [key, d] : wanted_)
            if (!resident_.count(key) && !building_.count(key) && !failed_.count(key)) queue_.push_back({d, key});
        std::sort(queue_.begin(), queue_.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
        if (queue_.size() > std::size_t(slots_)) queue_.erase(queue_.begin(), queue_.end() - slots_);
        queued = !queue_.empty();
    }
    if (queued) wake_.notify_one();
    wanted_.clear();
    ++frame_count_;
}

std::vector<DetailSlotData> DetailTileCache::take_uploads() {
    std::vector<DetailSlotData> out;
    out.swap(uploads_);
    return out;
}

int DetailTileCache::load_requested_now() {
    std::vector<std::pair<double, DetailTileKey>> keys;
    for (const auto& [key, d] : wanted_)
        if (!resident_.count(key)) keys.push_back({d, key});
    std::sort(keys.begin(), keys.end());
    // A load a frame waits for reports a tile it cannot read (InputError from the reader).
    int loaded = 0;
    for (const auto& [d, key] : keys) {
        if (resident_.size() >= std::size_t(slots_) && free_slots_.empty()) {
            bool evictable = false;
            for (const auto& [k, r] : resident_) evictable = evictable || r.last_used < frame_count_;
            if (!evictable) break;
        }
        admit(build(key, options_.shading.threads));
        ++loaded;
    }
    wanted_.clear();
    return loaded;
}

}  // namespace ts::fly
