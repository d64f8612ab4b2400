#include "core/tiles/tile_merge.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "core/tiles/mbtiles_file.hpp"
#include "core/tiles/mbtiles_reader.hpp"
#include "core/tiles/xyz_directory.hpp"
#include "core/util/error.hpp"
#include "core/util/shard_marker.hpp"

namespace {

namespace fs = std::filesystem;
using ts::tiles::TileId;

// Fake tile bytes: any bytes do, merge never decodes them.
std::vector<std::uint8_t> bytes_of(const TileId& t, int salt = 0) {
    return {std::uint8_t(t.z), std::uint8_t(t.x), std::uint8_t(t.y), std::uint8_t(salt), 0x89, 'P', 'N', 'G'};
}

struct TempDir {
    fs::path path;
    TempDir() : path(fs::temp_directory_path() / ("ts_merge_" + std::to_string(::getpid()) + "_" +
                                                  ::testing::UnitTest::GetInstance()->current_test_info()->name())) {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
};

const std::map<std::string, std::string> kMetadata = {{"name", "test"}, {"format", "png"}, {"minzoom", "0"}};
const std::string kJob = "{\"style\":\"hillshade\"}\n";

std::vector<TileId> all_tiles() {
    std::vector<TileId> v;
    for (int z = 0; z <= 3; ++z)
        for (int x = 0; x < (1 << z); ++x)
            for (int y = 0; y < (1 << z); ++y) v.push_back({z, x, y});
    return v;
}

void write_mbtiles(const fs::path& file, const std::vector<TileId>& tiles, const std::string& shard, int salt = 0,
                   std::map<std::string, std::string> metadata = kMetadata) {
    if (!shard.empty()) metadata["terrashade_shard"] = shard;
    ts::tiles::MbtilesFile f(file, metadata, kJob, ts::tiles::MbtilesFile::Existing::refuse);
    for (const TileId& t : tiles) f.put(t, bytes_of(t, salt));
    f.finish();
}

std::map<std::string, std::vector<std::uint8_t>> contents(const fs::path& file) {
    std::map<std::string, std::vector<std::uint8_t>> out;
    ts::tiles::MbtilesReader r(file);
    r.for_each_tile([&](const TileId& t, std::span<const std::uint8_t> b) {
        out[std::to_string(t.z) + "/" + std::to_string(t.x) + "/" + std::to_string(t.y)] = {b.begin(), b.end()};
    });
    return out;
}

// Tiles split 3 ways by index (merge does not care how the split was made).
std::vector<TileId> part(const std::vector<TileId>& all, int k, int n) {
    std::vector<TileId> v;
    for (std::size_t i = 0; i < all.size(); ++i)
        if (int(i % std::size_t(n)) == k) v.push_back(all[i]);
    return v;
}

TEST(TileMerge, MbtilesShardsEqualOneRun) {
    TempDir d;
    const auto all = all_tiles();
    write_mbtiles(d.path / "single.mbtiles", all, "");
    std::vector<fs::path> shards;
    for (int k = 0; k < 3; ++k) {
        shards.push_back(d.path / ("s" + std::to_string(k) + ".mbtiles"));
        write_mbtiles(shards.back(), part(all, k, 3), std::to_string(k) + "/3");
    }
    const auto stats = ts::tiles::merge_mbtiles({shards[2], shards[0], shards[1]}, d.path / "all.mbtiles");
    EXPECT_EQ(stats.tiles, all.size());
    EXPECT_EQ(stats.duplicates, 0u);
    EXPECT_EQ(contents(d.path / "all.mbtiles"), contents(d.path / "single.mbtiles"));
    EXPECT_EQ(ts::tiles::MbtilesReader(d.path / "all.mbtiles").metadata(),
              ts::tiles::MbtilesReader(d.path / "single.mbtiles").metadata());
    // Nothing but the output is left beside it.
    std::size_t files = 0;
    for (const auto& e : fs::directory_iterator(d.path)) files += e.path().filename().string().starts_with(".") ? 100 : 1;
    EXPECT_EQ(files, 5u);
}

TEST(TileMerge, MbtilesRefusesMissingConflictingAndForeignShards) {
    TempDir d;
    const auto all = all_tiles();
    for (int k = 0; k < 3; ++k) write_mbtiles(d.path / ("s" + std::to_string(k) + ".mbtiles"), part(all, k, 3), std::to_string(k) + "/3");
    const fs::path out = d.path / "all.mbtiles";
    EXPECT_THROW(ts::tiles::merge_mbtiles({d.path / "s0.mbtiles", d.path / "s2.mbtiles"}, out), ts::InputError);
    // Shard 1 again, with different bytes for its tiles, standing in for shard 1 of another job.
    write_mbtiles(d.path / "other1.mbtiles", part(all, 1, 3), "1/3", 7);
    write_mbtiles(d.path / "bad2.mbtiles", part(all, 1, 3), "2/3", 7);  // overlaps shard 1, other bytes
    EXPECT_THROW(ts::tiles::merge_mbtiles({d.path / "s0.mbtiles", d.path / "s1.mbtiles", d.path / "bad2.mbtiles"}, out),
                 ts::InputError);
    auto meta = kMetadata;
    meta["name"] = "another";
    write_mbtiles(d.path / "renamed2.mbtiles", part(all, 2, 3), "2/3", 0, meta);
    EXPECT_THROW(ts::tiles::merge_mbtiles({d.path / "s0.mbtiles", d.path / "s1.mbtiles", d.path / "renamed2.mbtiles"}, out),
                 ts::InputError);
    write_mbtiles(d.path / "plain.mbtiles", all, "");
    EXPECT_THROW(ts::tiles::merge_mbtiles({d.path / "plain.mbtiles"}, out), ts::InputError);
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(ts::tiles::MbtilesFile::partial_path(out)));
    // An identical overlap is kept once.
    write_mbtiles(d.path / "wide2.mbtiles", [&] {
        auto v = part(all, 2, 3);
        const auto extra = part(all, 1, 3);
        v.insert(v.end(), extra.begin(), extra.begin() + 3);
        return v;
    }(), "2/3");
    const auto stats = ts::tiles::merge_mbtiles({d.path / "s0.mbtiles", d.path / "s1.mbtiles", d.path / "wide2.mbtiles"}, out);
    EXPECT_EQ(stats.tiles, all.size());
    EXPECT_EQ(stats.duplicates, 3u);
}

void write_xyz(const fs::path& dir, const std::vector<TileId>& tiles, const ts::Shard* shard, int salt = 0) {
    ts::tiles::XyzDirectory x(dir, kJob, ts::tiles::XyzDirectory::Existing::refuse, 0, 3);
    for (const TileId& t : tiles) x.put(t, bytes_of(t, salt));
    if (shard) ts::write_shard_marker(dir, *shard);
}

TEST(TileMerge, XyzShardsEqualOneRunAndUnfinishedIsRefused) {
    TempDir d;
    const auto all = all_tiles();
    write_xyz(d.path / "single", all, nullptr);
    std::vector<fs::path> shards;
    for (int k = 0; k < 3; ++k) {
        shards.push_back(d.path / ("s" + std::to_string(k)));
        const ts::Shard s{k, 3};
        write_xyz(shards.back(), part(all, k, 3), k == 1 ? nullptr : &s);  // shard 1 unfinished
    }
    // A killed run's temporary file is not a tile.
    std::ofstream(shards[0] / "3" / ".5.tmp-1-2.png") << "partial";
    const fs::path out = d.path / "all";
    EXPECT_THROW(ts::tiles::merge_xyz(shards, out), ts::InputError);
    EXPECT_FALSE(fs::exists(out));
    ts::write_shard_marker(shards[1], {1, 3});
    const auto stats = ts::tiles::merge_xyz(shards, out);
    EXPECT_EQ(stats.tiles, all.size());
    for (const TileId& t : all) {
        const fs::path rel = fs::path(std::to_string(t.z)) / std::to_string(t.x) / (std::to_string(t.y) + ".png");
        std::ifstream a(d.path / "single" / rel, std::ios::binary), b(out / rel, std::ios::binary);
        EXPECT_EQ(std::string(std::istreambuf_iterator<char>(a), {}), std::string(std::istreambuf_iterator<char>(b), {}));
    }
    EXPECT_TRUE(fs::exists(out / ts::tiles::XyzDirectory::kJobFile));
    EXPECT_FALSE(fs::exists(out / ts::kShardMarkerFile));
    // An existing output is not overwritten.
    EXPECT_THROW(ts::tiles::merge_xyz(shards, out), ts::InputError);
}

}  // namespace
