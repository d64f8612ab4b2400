#include "app/insolation_shards.hpp"

#include <algorithm>
#include <cstring>

#include <nlohmann/json.hpp>

#include "core/raster/float_cog_writer.hpp"
#include "core/raster/float_tiff_reader.hpp"
#include "core/raster/image_writer_registry.hpp"
#include "core/util/error.hpp"

namespace ts::app {
namespace {

constexpr const char* kKind = "terrashade insolation shard";
// A merge holds every shard and the merged map: beyond this many values it is refused before
// reading (16 GB of floats), rather than failing half way.
constexpr std::size_t kMaxMergeValues = std::size_t(4) << 30;

}  // namespace

std::string insolation_shard_text(const InsolationShardRecord& r) {
    const nlohmann::json j = {{"kind", kKind},       {"job", r.job},   {"shard", shard_text(r.shard)},
                              {"row0", r.row0},      {"rows", r.rows}, {"height", r.height},
                              {"bands", r.bands},    {"units", r.units}};
    return j.dump();
}

std::optional<InsolationShardRecord> parse_insolation_shard(const std::string& text) {
    try {
        const nlohmann::json j = nlohmann::json::parse(text);
        if (!j.is_object() || j.value("kind", "") != kKind) return std::nullopt;
        InsolationShardRecord r;
        r.job = j.at("job").get<std::string>();
        r.shard = parse_shard(j.at("shard").get<std::string>(), "the shard's record: ");
        r.row0 = j.at("row0").get<int>(), r.rows = j.at("rows").get<int>(), r.height = j.at("height").get<int>();
        r.bands = j.at("bands").get<std::vector<std::string>>();
        r.units = j.at("units").get<std::vector<std::string>>();
        if (r.row0 < 0 || r.rows <= 0 || r.row0 + r.rows > r.height) return std::nullopt;
        return r;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

bool is_insolation_shard_path(const std::string& path) {
    return raster::written_as(path, raster::ImageWriter::geotiff);
}

InsolationMergeStats merge_insolation_shards(const std::vector<std::filesystem::path>& shards,
                                             const std::filesystem::path& out) {
    std::vector<raster::FloatTiff> parts;
    std::vector<InsolationShardRecord> records;
    std::vector<std::string> names;
    std::vector<std::optional<Shard>> found;
    std::size_t values = 0;
    for (const auto& path : shards) {
        raster::FloatTiff t = raster::read_float_tiff(path, kMaxMergeValues - std::min(values, kMaxMergeValues));
        values += t.values.size();
        const std::optional<InsolationShardRecord> r = parse_insolation_shard(t.image_description);
        names.push_back(path.string());
        found.push_back(r ? std::optional<Shard>(r->shard) : std::nullopt);
        if (r) {
            if (!records.empty() && r->job != records.front().job)
                throw input_error(path.string(), "is a shard of another insolation job than " + names.front() +
                                                     " (other options or DEM)");
            if (t.height != r->rows || int(r->bands.size()) != t.bands)
                throw input_error(path.string(), "does not hold the rows and bands its record says");
            records.push_back(*r);
        } else {
            records.push_back({});
        }
        parts.push_back(std::move(t));
    }
    check_complete_shard_set(names, found);  // every input a shard, all N of one job, each once
    // Shard K holds the rows after shard K-1's: together 0..height-1, once each.
    std::vector<std::size_t> order(parts.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[std::size_t(records[i].shard.index)] = i;
    const InsolationShardRecord& first = records[order.front()];
    const raster::FloatTiff& top = parts[order.front()];
    int next_row = 0;
    for (std::size_t k : order) {
        if (records[k].row0 != next_row || parts[k].width != top.width || parts[k].bands != top.bands ||
            records[k].height != first.height)
            throw input_error(names[k], "does not continue the map of the shards before it (rows " +
                                            std::to_string(records[k].row0) + ".., expected " +
                                            std::to_string(next_row) + "..)");
        next_row += records[k].rows;
    }
    if (next_row != first.height) throw input_error(names[order.back()], "the shards' rows do not reach the map's end");

    const int width = top.width, height = first.height, bands = top.bands;
    const std::size_t plane = std::size_t(width) * std::size_t(height);
    std::vector<float> map(plane * std::size_t(bands));
    for (std::size_t k : order) {
        const std::size_t offset = std::size_t(records[k].row0) * std::size_t(width);
        const std::size_t count = std::size_t(records[k].rows) * std::size_t(width);
        for (int b = 0; b < bands; ++b)
            std::memcpy(map.data() + std::size_t(b) * plane + offset, parts[k].band(b), count * sizeof(float));
    }
    const geo::Georef& g = top.georef;
    const geo::Georef georef(width, height, g.transform(), g.crs_ptr(), g.pixel_is_area());
    raster::write_float_cog(out, width, height, bands, map.data(), georef, first.bands, first.units);
    return {parts.size(), width, height, bands};
}

}  // namespace ts::app
