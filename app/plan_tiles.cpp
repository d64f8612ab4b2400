// `terrashade plan tiles`: the tiles per zoom of a tile job, the shards that fit it into a wall
// time, and the storage, from a measured sample (or a given rate). docs/scale.md.
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <memory>
#include <string>

#include "app/dem_input.hpp"
#include "app/options/within_range.hpp"
#include "app/tiles_options.hpp"
#include "app/wall_time.hpp"
#include "core/light/utc_time.hpp"
#include "core/render/render_scene.hpp"
#include "core/tiles/tile_count.hpp"
#include "core/tiles/tile_export.hpp"
#include "core/util/error.hpp"

namespace ts::app {
namespace {

struct PlanTilesArgs {
    DemInput dem;
    TilesArgs tiles;
    std::string wall_time = "1h";
    double rate = 0;
    int sample = 200;
    int max_parallel = 0;
};

// A sample's tiles are counted and measured, not kept.
class CountingSink final : public tiles::TileSink {
public:
    bool has(const tiles::TileId&) const override { return false; }
    void put(const tiles::TileId&, std::vector<std::uint8_t> png) override { bytes_ += png.size(); }
    void finish() override {}
    std::uint64_t bytes() const { return bytes_; }

private:
    std::atomic<std::uint64_t> bytes_{0};
};

// Above this many tiles the sample's plan (the list of all tiles) is not built: give --rate.
constexpr std::int64_t kMaxListedTiles = 20'000'000;
// Bytes of a stored tile when nothing was sampled (a grey 256-px relief PNG of hilly terrain).
constexpr double kDefaultTileBytes = 30000;

void run_plan_tiles(const PlanTilesArgs& a) {
    tiles::TileJob job = tile_job(a.tiles);
    const double wall_s = parse_wall_time(a.wall_time);
    if (a.rate < 0) throw InputError("--rate: tiles per second per shard, > 0");
    if (a.sample < 0) throw InputError("--sample: a number of tiles >= 0");
    const dem::Dem dem = load_dem_input(a.dem);
    job.shading.grid_north_deg = dem.georef.grid_azimuth_of_north_deg();
    if (!a.tiles.time.empty()) {
        const render::SunState sun = render::sun_at_dem_centre(dem, light::parse_utc_time(a.tiles.time));
        job.shading.sun_azimuth_deg = sun.azimuth_deg, job.shading.sun_elevation_deg = sun.elevation_deg;
    }
    const tiles::LonLatBox box = tiles::terrain_footprint(dem);  // as tiles plans them
    std::int64_t total = 0;
    std::printf("tiles of %s, zoom %d-%d, %d px, %s:\n  zoom        tiles\n", a.dem.files.front().c_str(), job.z0,
                job.z1, job.tile_size, std::string(job.shading.style->name()).c_str());
    for (int z = job.z0; z <= job.z1; ++z) {
        const std::int64_t n = tiles::count_tiles_covering(box, z);
        std::printf("  %4d %12lld\n", z, static_cast<long long>(n));
        total += n;
    }
    std::printf("  all  %12lld\n", static_cast<long long>(total));
    if (total == 0) throw input_error(dem.source, "covers no Web Mercator tile (it lies beyond +-85.05 deg latitude?)");

    // The sample: one shard of about `sample` tiles, so it has a shard's mix of zooms and its
    // shading of every DEM level (each shard pays that once).
    double shading_s = 0, tiles_per_s = a.rate, tile_bytes = kDefaultTileBytes, stored_fraction = 1;
    bool measured = false;
    if (a.sample > 0 && (a.rate == 0 || total <= kMaxListedTiles)) {
        if (total > kMaxListedTiles)
            throw InputError("plan tiles: " + std::to_string(total) +
                             " tiles are too many to sample from; give --rate TILES_PER_S (e.g. from a smaller region)");
        tiles::TileJob sample_job = job;
        sample_job.shard = {0, int(std::clamp<std::int64_t>(total / a.sample, 1, kMaxShards))};
        CountingSink sink;
        const tiles::TileExportStats s = tiles::export_tiles(dem, sample_job, sink, nullptr);
        const std::size_t made = s.written + s.empty;
        if (made > 0) {
            measured = true;
            shading_s = s.source_seconds;
            if (a.rate == 0) tiles_per_s = made / std::max(s.tile_seconds, 1e-9);
            if (s.written > 0) tile_bytes = double(sink.bytes()) / double(s.written);
            stored_fraction = double(s.written) / double(made);
            std::printf("sample: %zu tiles (shard %s): shading the DEM levels %.2f s, tiles %.2f s (%.0f tiles/s), "
                        "%zu with data, %.0f bytes each\n",
                        made, shard_text(sample_job.shard).c_str(), s.source_seconds, s.tile_seconds,
                        made / std::max(s.tile_seconds, 1e-9), s.written, tile_bytes);
        }
    }
    if (!(tiles_per_s > 0)) throw InputError("plan tiles: nothing to measure; give --rate TILES_PER_S");
    if (a.rate > 0) std::printf("rate: %.1f tiles/s per shard (--rate)\n", a.rate);

    const double work_s = double(total) / tiles_per_s;
    const std::int64_t shards = shards_for_wall_time(work_s, shading_s, wall_s);
    if (shards == 0)
        throw InputError("plan tiles: shading the DEM levels alone takes " + format_duration(shading_s) +
                         " per shard, more than --wall-time " + a.wall_time);
    const double shard_s = shading_s + work_s / double(shards);
    std::printf("one process: %s (%s shading + %s tiles)\n", format_duration(shading_s + work_s).c_str(),
                format_duration(shading_s).c_str(), format_duration(work_s).c_str());
    std::printf("shards: %lld for --wall-time %s: ~%lld tiles and %s each, %.2f shard-hours in all (node-hours with one shard per node)\n",
                static_cast<long long>(shards), a.wall_time.c_str(), static_cast<long long>(total / shards),
                format_duration(shard_s).c_str(), double(shards) * shard_s / 3600.0);
    const int parallel = a.max_parallel > 0 ? int(std::min<std::int64_t>(a.max_parallel, shards)) : int(shards);
    std::printf("slurm: sbatch --array=0-%lld%%%d --time=%s (scripts/slurm_shards.sh)%s\n",
                static_cast<long long>(shards - 1), parallel, slurm_time(wall_s).c_str(),
                shards > 1001 ? "; above the default MaxArraySize of 1001: raise it or run several arrays "
                                "(docs/scale.md)"
                              : "");
    const double stored = double(total) * stored_fraction;
    std::printf("storage: %s for ~%.0f tiles with data%s\n", format_bytes(stored * tile_bytes).c_str(), stored,
                measured ? " (bytes per tile from the sample)" : " (30 KB per tile assumed: no sample)");
}

}  // namespace

void add_plan_tiles_command(CLI::App& plan) {
    auto a = std::make_shared<PlanTilesArgs>();
    CLI::App* cmd = plan.add_subcommand("tiles", "The work of a `tiles` job: tiles per zoom, shards for a wall time, "
                                                 "storage (the same DEM and tile options as `tiles`)");
    add_dem_input_options(*cmd, a->dem);
    add_tiles_options(*cmd, a->tiles);
    cmd->add_option("--wall-time", a->wall_time, "Wall time one shard may take (2h, 1h30m, 45m, HH:MM:SS)")
        ->capture_default_str();
    cmd->add_option("--rate", a->rate, "Tiles per second of one shard, instead of the measured sample's");
    cmd->add_option("--sample", a->sample, "Tiles to make (and throw away) to measure the rate and bytes per tile; 0: "
                                           "none (give --rate)")
        ->capture_default_str();
    cmd->add_option("--max-parallel", a->max_parallel, "Shards running at once (the %K of sbatch --array; default all)")
        ->check(within(1, 100000));
    cmd->callback([a] { run_plan_tiles(*a); });
}

}  // namespace ts::app
