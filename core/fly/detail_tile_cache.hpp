#pragma once
// The detail tiles of a streamed DEM resident at a time (core/fly/detail_tile.hpp), within a
// memory budget, loaded on a worker thread while frames go on.
//
// Each frame the CDLOD selection asks for the finer levels' node ranges (CdlodDetail): a node
// whose tile is resident is answered; one whose tile is not is drawn coarser and its tile is
// requested. update() then hands the requests, and the tiles within the prefetch radius of the
// eye, to the worker nearest first, takes the tiles it finished (lit for the current sun), and
// evicts the least recently used tiles beyond the budget. Every resident tile has a slot of the
// renderer's tile atlas; the slots whose contents changed (a new tile, a new sun) are listed
// for the renderer to upload.
//
// Threads: every public method is for the thread that draws; the worker only builds tiles.
#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include <glm/vec3.hpp>

#include "core/fly/cdlod_tree.hpp"
#include "core/fly/detail_tile.hpp"
#include "core/fly/grid_frame.hpp"

namespace ts::fly {

struct DetailCacheOptions {
    // What the resident tiles may hold in all (their shading state and GPU copy).
    std::size_t budget_bytes = std::size_t(2) << 30;
    // Tiles nearer than this to the eye (metres, horizontally) are loaded before the view asks.
    double prefetch_m = 0;
    // Threads that shade a tile on the worker while frames are drawn: one leaves the other cores
    // to the frames (a CPU Vulkan device draws with them). Loads a frame waits for use
    // shading.threads (0: every core).
    int worker_threads = 1;
    DetailShadingOptions shading;
};

// One resident tile's data for the renderer's atlas.
struct DetailSlotData {
    int slot = 0;
    int col0 = 0, row0 = 0, samples_x = 0, samples_y = 0;
    const std::vector<float>* heights = nullptr;
    std::vector<std::uint32_t> radiance, sun;  // 2 and 4 words a sample (radiance_pack.hpp)
};

class DetailTileCache final : public CdlodDetail {
public:
    DetailTileCache(const dem::DemSource& source, const TerrainOverview& overview, const visibility::FarField& far,
                    const GridFrame& frame, int patch_quads, const DetailCacheOptions& options);
    ~DetailTileCache() override;
    DetailTileCache(const DetailTileCache&) = delete;
    DetailTileCache& operator=(const DetailTileCache&) = delete;

    const DetailTileLayout& layout() const { return layout_; }
    // How many tiles the budget holds (the atlas's slot count), and the bytes of one.
    int slots() const { return slots_; }
    std::size_t tile_bytes() const { return tile_bytes_; }

    bool node_z_range(int level, int ix, int iy, glm::vec2& z) override;
    void request(int level, int ix, int iy, double distance_m) override;

    // The prefetch radius (metres): the finest overview level's range, with a margin.
    void set_prefetch(double metres) { options_.prefetch_m = metres; }
    // A new sun for every tile: the resident ones are lit again (their slots listed for upload).
    void set_sun(const render::SunState& sun);
    // After a frame's selection: requests and prefetch to the worker, finished tiles in, LRU out.
    void update(const glm::dvec3& eye);
    // Loads every requested tile now, on this thread (offscreen frames: the same pixels as a
    // window that waited). Returns how many it loaded.
    int load_requested_now();
    // The slots to upload since the last call.
    std::vector<DetailSlotData> take_uploads();
    // The resident tile's slot at node (level, ix, iy), -1 if none.
    int slot_of_node(int level, int ix, int iy) const;
    // The resident tile holding a level-0 position, null if none.
    const DetailTile* tile_at(double col, double row) const;

    std::size_t resident() const { return resident_.size(); }
    std::size_t resident_bytes() const { return resident_.size() * tile_bytes_; }
    std::size_t peak_resident_bytes() const { return peak_bytes_; }
    std::uint64_t loaded() const { return loaded_; }
    std::size_t pending() const;

private:
    struct Resident {
        std::unique_ptr<DetailTile> tile;
        int slot = 0;
        std::uint64_t last_used = 0;
        std::uint64_t sun_generation = 0;
    };
    void worker_loop();
    std::unique_ptr<DetailTile> build(DetailTileKey key, int threads) const;
    void admit(std::unique_ptr<DetailTile> tile);
    void lit_upload(Resident& r);

    const dem::DemSource& source_;
    const TerrainOverview& overview_;
    const visibility::FarField& far_;
    const GridFrame& frame_;
    DetailTileLayout layout_;
    DetailCacheOptions options_;
    int slots_ = 0;
    std::size_t tile_bytes_ = 0;
    std::map<DetailTileKey, Resident> resident_;
    std::vector<int> free_slots_;
    std::vector<DetailSlotData> uploads_;
    std::map<DetailTileKey, double> wanted_;  // this frame's requests, nearest distance
    std::uint64_t frame_count_ = 0;
    std::size_t peak_bytes_ = 0;
    std::uint64_t loaded_ = 0;
    render::SunState sun_{};
    std::uint64_t sun_generation_ = 0;

    // Shared with the worker.
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::vector<std::pair<double, DetailTileKey>> queue_;  // nearest last
    std::set<DetailTileKey> building_;
    std::set<DetailTileKey> failed_;
    std::vector<std::unique_ptr<DetailTile>> done_;
    bool stop_ = false;
    std::thread worker_;
};

}  // namespace ts::fly
