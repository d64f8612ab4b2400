#include "app/bench/tile_knobs_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include "app/bench/csv_number.hpp"
#include "core/raster/png_writer.hpp"
#include "core/raster/srgb.hpp"
#include "core/terrain/height_pyramid.hpp"
#include "core/tiles/shade_source.hpp"
#include "core/tiles/tile_pixels.hpp"
#include "core/tiles/tile_renderer.hpp"
#include "core/util/atomic_file.hpp"
#include "core/util/error.hpp"
#include "core/util/stopwatch.hpp"

namespace ts::app {
namespace {

struct KnobRow {
    std::string knob, value;
    bool is_default = false;
    double seconds = 0, rms_codes = 0, max_codes = 0;
};

int code(float linear) { return int(std::lround(255.0f * raster::srgb_oetf(std::clamp(linear, 0.0f, 1.0f)))); }

// RMS and max of the sRGB-code difference of two sources of one level (void texels skipped).
void compare(const tiles::ShadeSource& got, const tiles::ShadeSource& ref, KnobRow& row) {
    double sum2 = 0, worst = 0;
    std::size_t n = 0;
    for (std::size_t k = 0; k < ref.values.size(); ++k) {
        if (std::isnan(ref.values[k]) || std::isnan(got.values[k])) continue;
        const double e = std::abs(code(got.values[k]) - code(ref.values[k]));
        sum2 += e * e, worst = std::max(worst, e), ++n;
    }
    row.rms_codes = n ? std::sqrt(sum2 / double(n)) : 0.0;
    row.max_codes = worst;
}

// Tiles of `zoom` cut from `source`, encoded as the export would (the encoding is timed, not kept).
std::vector<tiles::TileImage> cut_tiles(const dem::Dem& dem, const tiles::TileJob& job, int zoom,
                                        const tiles::ShadeSource& source) {
    const tiles::TilePixelMap map(dem);
    tiles::TileScratch scratch;
    const raster::PngEncoding encoding;
    tiles::TileJob at = job;
    at.z0 = at.z1 = zoom;
    std::vector<tiles::TileImage> out;
    for (const tiles::TileId& t : tiles::plan_tiles(dem, at)) {
        tiles::TileImage img;
        tiles::render_tile(map, source, job.shading, tiles::tile_frame(t, job.tile_size), scratch, img);
        if (img.covered) (void)raster::encode_png(img.size, img.size, img.channels, img.pixels.data(), encoding);
        out.push_back(std::move(img));
    }
    return out;
}

void level_bias_rows(const dem::Dem& dem, const tiles::TileJob& job, int zoom, std::vector<KnobRow>& rows) {
    const int pixel_zoom = zoom + tiles::tile_size_shift(job.tile_size);
    tiles::TileJob unbiased = job;
    unbiased.level_bias = 0;
    const int matched = tiles::zoom_shading(dem, unbiased, pixel_zoom).level;
    if (matched == 0) return;  // past the DEM's native zoom: no finer level to compare with
    int max_level = 0;  // as zoom_shading bounds it
    for (int b = 1; b <= 8; ++b) {
        tiles::TileJob j = unbiased;
        j.level_bias = b;
        max_level = std::max(max_level, tiles::zoom_shading(dem, j, pixel_zoom).level);
    }
    const double scale = tiles::zoom_shading(dem, unbiased, pixel_zoom).vertical_scale;
    tiles::TileShading whole = job.shading;
    whole.block_texels = 0;
    // The reference: level 0 shaded, then averaged 2x2 `matched` times.
    tiles::ShadeSource reference = tiles::make_shade_source(dem, whole, 0, scale);
    for (int l = 0; l < matched; ++l) {
        reference.values = terrain::downsample_2x2(reference.values.data(), reference.width, reference.height, false,
                                                   whole.threads);
        reference.width = (reference.width + 1) / 2, reference.height = (reference.height + 1) / 2;
        ++reference.level;
    }
    const std::vector<tiles::TileImage> want = cut_tiles(dem, job, zoom, reference);
    std::printf("tile knobs: zoom %d matches level %d; --level-bias against level 0 averaged to it\n", zoom, matched);
    for (int level = 0; level <= std::min(max_level, matched + 2); ++level) {
        const int bias = level - matched;
        Stopwatch t;
        const tiles::ShadeSource source = tiles::make_shade_source(dem, whole, level, scale);
        const std::vector<tiles::TileImage> got = cut_tiles(dem, job, zoom, source);
        KnobRow row{"level_bias_z" + std::to_string(zoom), std::to_string(bias), bias == 0};
        row.seconds = t.seconds();
        double sum2 = 0, worst = 0;
        std::size_t n = 0;
        for (std::size_t i = 0; i < got.size(); ++i) {
            const tiles::TileImage &g = got[i], &w = want[i];
            if (g.pixels.size() != w.pixels.size() || g.channels != w.channels) continue;
            const std::size_t ch = std::size_t(g.channels);
            for (std::size_t p = 0; p + ch <= g.pixels.size(); p += ch) {
                if (g.pixels[p + ch - 1] != 255 || w.pixels[p + ch - 1] != 255) continue;  // alpha
                const double e = std::abs(int(g.pixels[p]) - int(w.pixels[p]));
                sum2 += e * e, worst = std::max(worst, e), ++n;
            }
        }
        row.rms_codes = n ? std::sqrt(sum2 / double(n)) : 0.0;
        row.max_codes = worst;
        rows.push_back(row);
        std::printf("  %-13s %-9s %7.2f s  rms %.3f codes, max %.0f (level %d)\n", row.knob.c_str(),
                    row.value.c_str(), row.seconds, row.rms_codes, row.max_codes, level);
        std::fflush(stdout);
    }
}

}  // namespace

void run_tile_knobs_study(const dem::Dem& dem, tiles::TileJob job, const std::string& csv_path) {
    job.shading.style = tiles::find_tile_style("relief");
    const tiles::TileShading defaults = job.shading;
    const int pixel_zoom = job.z1 + tiles::tile_size_shift(job.tile_size);
    const tiles::ZoomShading zs = tiles::zoom_shading(dem, job, pixel_zoom);
    std::vector<KnobRow> rows;
    std::printf("tile knobs: relief at zoom %d (level %d), %d directions\n", job.z1, zs.level, defaults.directions);

    // The level shaded whole: the reference of every block setting.
    tiles::TileShading whole = defaults;
    whole.block_texels = 0;
    Stopwatch watch;
    const tiles::ShadeSource reference = tiles::make_shade_source(dem, whole, zs.level, zs.vertical_scale);
    const double whole_s = watch.seconds();
    const int side = std::max(reference.width, reference.height);
    // Blocks small enough that this DEM is cut into several (a small DEM fits one by default).
    const int block = std::max(64, side / 4);
    const int halo = std::max(8, block / 8);
    std::printf("tile knobs: %dx%d texels, whole level %.2f s; blocks of %d texels\n", reference.width,
                reference.height, whole_s, block);
    auto blocks = [&](const std::string& knob, const std::string& value, bool is_default, tiles::TileShading s) {
        KnobRow row{knob, value, is_default};
        Stopwatch t;
        const tiles::ShadeSource got = tiles::make_shade_source(dem, s, zs.level, zs.vertical_scale);
        row.seconds = t.seconds();
        compare(got, reference, row);
        rows.push_back(row);
        std::printf("  %-13s %-9s %7.2f s  rms %.3f codes, max %.0f\n", knob.c_str(), value.c_str(), row.seconds,
                    row.rms_codes, row.max_codes);
        std::fflush(stdout);
    };
    for (const tiles::FarFieldMethod m : {tiles::FarFieldMethod::exact, tiles::FarFieldMethod::fast,
                                          tiles::FarFieldMethod::balanced, tiles::FarFieldMethod::fine,
                                          tiles::FarFieldMethod::finest}) {
        tiles::TileShading s = defaults;
        s.block_texels = block, s.block_halo_texels = halo, s.far_field = m;
        blocks("far_field", std::string(tiles::far_field_name(m)), m == defaults.far_field, s);
    }
    for (const int h : {halo / 2, halo, 2 * halo, 4 * halo, defaults.block_halo_texels}) {
        tiles::TileShading s = defaults;
        s.block_texels = block, s.block_halo_texels = h;
        blocks("block_halo", std::to_string(h), h == defaults.block_halo_texels, s);
    }
    for (const int b : {block / 2, block, 2 * block}) {
        tiles::TileShading s = defaults;
        s.block_texels = b, s.block_halo_texels = halo;
        blocks("block_texels", std::to_string(b), false, s);
    }
    rows.push_back({"block_texels", "whole", true, whole_s, 0.0, 0.0});

    // Tile size: the same ground as 256-px tiles of z1 and as 512-px tiles of z1-1, from the one
    // source (both pixel zooms are pixel_zoom), cut and encoded.
    if (job.z1 >= 1 && job.tile_size == 256) {
        const tiles::TilePixelMap map(dem);
        tiles::TileScratch scratch;
        tiles::TileImage small, large;
        const raster::PngEncoding encoding;
        tiles::TileJob big = job;
        big.tile_size = 512, big.z0 = big.z1 = job.z1 - 1;
        tiles::TileJob fine = job;
        fine.z0 = job.z1;
        double small_s = 0, large_s = 0, sum2 = 0, worst = 0;
        std::size_t n = 0;
        for (const tiles::TileId& t : tiles::plan_tiles(dem, big)) {
            Stopwatch tl;
            tiles::render_tile(map, reference, defaults, tiles::tile_frame(t, 512), scratch, large);
            if (large.covered) (void)raster::encode_png(512, 512, large.channels, large.pixels.data(), encoding);
            large_s += tl.seconds();
            for (int q = 0; q < 4; ++q) {
                const tiles::TileId c{t.z + 1, 2 * t.x + (q & 1), 2 * t.y + (q >> 1)};
                Stopwatch ts;
                tiles::render_tile(map, reference, defaults, tiles::tile_frame(c, 256), scratch, small);
                if (small.covered) (void)raster::encode_png(256, 256, small.channels, small.pixels.data(), encoding);
                small_s += ts.seconds();
                const int ch = small.channels;
                for (int r = 0; r < 256; ++r)
                    for (int col = 0; col < 256; ++col)
                        for (int k = 0; k < ch; ++k) {
                            const std::size_t i = (std::size_t(r) * 256 + std::size_t(col)) * std::size_t(ch) + std::size_t(k);
                            const std::size_t j = ((std::size_t(r + 256 * (q >> 1))) * 512 +
                                                   std::size_t(col + 256 * (q & 1))) * std::size_t(ch) + std::size_t(k);
                            const double e = std::abs(int(small.pixels[i]) - int(large.pixels[j]));
                            sum2 += e * e, worst = std::max(worst, e), ++n;
                        }
            }
        }
        const double rms = n ? std::sqrt(sum2 / double(n)) : 0.0;
        rows.push_back({"tile_size", "256", true, small_s, rms, worst});
        rows.push_back({"tile_size", "512", false, large_s, rms, worst});
        std::printf("  tile_size     256       %7.2f s, 512 %.2f s for the same ground; rms %.3f codes, max %.0f "
                    "between them\n", small_s, large_s, rms, worst);
    }

    // Pyramid level per zoom: each zoom's tiles shaded from levels around the one its pixels
    // match (--level-bias), against the finest level's relief averaged down to that level's
    // texels (an area mean of the picture itself, not of the heights), all cut the same way;
    // the zooms from z0 that have a finer level than their own.
    for (int z = job.z0; z <= job.z1; ++z) level_bias_rows(dem, job, z, rows);

    write_atomically(csv_path, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out << "knob,value,is_default,seconds,rms_codes,max_codes\n";
        for (const KnobRow& r : rows)
            out << r.knob << ',' << r.value << ',' << (r.is_default ? 1 : 0) << ',' << csv_number(r.seconds) << ','
                << csv_number(r.rms_codes) << ',' << csv_number(r.max_codes) << '\n';
        if (!out.flush()) throw input_error(csv_path, "cannot write");
    });
    std::printf("wrote %s (%zu rows)\n", csv_path.c_str(), rows.size());
}

}  // namespace ts::app
