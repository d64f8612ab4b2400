// `terrashade merge`: the shards of a tile set (MBTiles files or XYZ folders) or of a relit
// frame series into one output equal to a single-process run (docs/scale.md). The work is
// core/tiles/tile_merge.hpp and core/render/frame_series_merge.hpp.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "app/insolation_shards.hpp"
#include "app/io_plan.hpp"
#include "core/render/frame_series_merge.hpp"
#include "core/tiles/tile_merge.hpp"
#include "core/util/error.hpp"
#include "core/util/stopwatch.hpp"
#include "core/raster/image_writer_registry.hpp"

namespace ts::app {
namespace {

namespace fs = std::filesystem;

struct MergeArgs {
    std::vector<std::string> inputs;
    std::string out;
};

enum class ShardKind { mbtiles, xyz, frames, insolation };

ShardKind kind_of(const std::string& input) {
    std::error_code ec;
    if (raster::written_as(input, raster::ImageWriter::mbtiles)) return ShardKind::mbtiles;
    if (is_insolation_shard_path(input)) {
        if (!fs::is_regular_file(input, ec)) throw input_error(input, "no such shard (an insolation --shard GeoTIFF)");
        return ShardKind::insolation;
    }
    if (!fs::is_directory(input, ec)) throw input_error(input, "no such shard (an .mbtiles file or a folder)");
    if (fs::exists(fs::path(input) / "times.csv", ec)) return ShardKind::frames;
    return ShardKind::xyz;
}

const char* kind_name(ShardKind k) {
    return k == ShardKind::mbtiles      ? "MBTiles files"
           : k == ShardKind::xyz        ? "XYZ tile folders"
           : k == ShardKind::insolation ? "insolation GeoTIFFs"
                                        : "relight folders";
}

void run_merge(const MergeArgs& a) {
    const ShardKind kind = kind_of(a.inputs.front());
    std::vector<fs::path> shards;
    for (const std::string& in : a.inputs) {
        if (kind_of(in) != kind)
            throw input_error(in, std::string("is not like ") + a.inputs.front() + ": give only " + kind_name(kind));
        shards.emplace_back(in);
    }
    const bool files = kind == ShardKind::mbtiles || kind == ShardKind::insolation;
    if (kind == ShardKind::insolation) {
        if (!is_insolation_shard_path(a.out))
            throw input_error(a.out, "insolation shards merge into a GeoTIFF (.tif or .tiff)");
    } else if ((kind == ShardKind::mbtiles) != raster::written_as(a.out, raster::ImageWriter::mbtiles)) {
        throw input_error(a.out, kind == ShardKind::mbtiles ? "MBTiles shards merge into an .mbtiles file"
                                                            : "folders merge into a folder, not an .mbtiles file");
    }
    IoPlan plan;
    for (const std::string& in : a.inputs) files ? plan.input("shard", in) : plan.input_directory("shard", in);
    if (kind == ShardKind::mbtiles)
        plan.output("--out", a.out, raster::tile_set_extensions());
    else if (kind == ShardKind::insolation)
        plan.output("--out", a.out, raster::float_raster_extensions());
    else
        plan.output_directory("--out", a.out);
    plan.check();
    const Stopwatch watch;
    if (kind == ShardKind::insolation) {
        std::vector<fs::path> paths(a.inputs.begin(), a.inputs.end());
        const InsolationMergeStats s = merge_insolation_shards(paths, a.out);
        std::printf("merged %zu shards: a %dx%d map of %d bands into %s (%.2f s)\n", s.shards, s.width, s.height,
                    s.bands, a.out.c_str(), watch.seconds());
        return;
    }
    if (kind == ShardKind::frames) {
        const render::FrameMergeStats s = render::merge_frame_series(shards, a.out);
        std::printf("merged %zu shards: %zu frames with times.csv into %s (%.2f s)\n", s.shards, s.frames,
                    a.out.c_str(), watch.seconds());
        return;
    }
    const tiles::MergeStats s = kind == ShardKind::mbtiles ? tiles::merge_mbtiles(shards, a.out)
                                                           : tiles::merge_xyz(shards, a.out);
    std::printf("merged %zu shards: %zu tiles", s.shards, s.tiles);
    if (s.duplicates) std::printf(", %zu identical duplicates kept once", s.duplicates);
    std::printf(" into %s (%.2f s)\n", a.out.c_str(), watch.seconds());
}

}  // namespace

void add_merge_command(CLI::App& root) {
    auto a = std::make_shared<MergeArgs>();
    CLI::App* cmd = root.add_subcommand(
        "merge",
        "Merge the shards of one job (tiles --shard K/N: MBTiles files or XYZ folders; relight --shard K/N: frame "
        "folders; insolation --shard K/N: GeoTIFFs) into one output equal to a single run; refuses missing, unfinished or conflicting shards "
        "(docs/scale.md)");
    cmd->add_option("shards", a->inputs, "The N shards: SHARD.mbtiles..., or tile folders, or relight folders, or insolation SHARD.tif...")
        ->required();
    cmd->add_option("-o,--out", a->out, "The merged output: ALL.mbtiles, a new folder, or ALL.tif")->required();
    cmd->callback([a] { run_merge(*a); });
}

}  // namespace ts::app
