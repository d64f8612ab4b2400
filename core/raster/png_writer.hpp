#pragma once
// 8-bit PNG through libpng. Kept apart from OpenImageIO on purpose: linking OIIO pulls ~260
// shared libraries whose symbol resolution cost every terrashade run 0.3 s at start-up (perf:
// 70% in the dynamic loader), more than the shading itself.
#include <cstdint>
#include <filesystem>

namespace ts::raster {

// How the pixels are compressed. The defaults were measured on rendered frames (500x500 map,
// 640x360 perspective views; CPU time of one encode, libpng 1.6 / zlib 1.2):
//   libpng's default (zlib 6, adaptive filter)  map 46 ms 463 KB   perspective 34 ms 128 KB
//   zlib 3, Sub filter (default here)           map 16 ms 428 KB   perspective  9 ms 134 KB
//   zlib 1, Sub filter                          map 11 ms 441 KB   perspective  5 ms 150 KB
// i.e. 3-4x faster for -8% (maps) to +4% (hazy perspective views) in size. Sub predicts a pixel
// from its left neighbour, which suits shaded terrain; the adaptive choice per row buys nothing
// here and costs a trial of all five filters on every row.
struct PngEncoding {
    int zlib_level = 3;       // 0 (store) .. 9 (smallest)
    bool sub_filter = true;   // false: libpng's adaptive choice among all five filters
};

// Writes width x height pixels of 1 (grey), 3 (RGB) or 4 (RGBA) interleaved 8-bit channels,
// row-major from the top row. Not atomic by itself: callers go through write_atomically.
// Throws ts::InputError naming `shown_path` on failure.
void write_png(const std::filesystem::path& file, const std::filesystem::path& shown_path, int width, int height,
               int channels, const std::uint8_t* data, const PngEncoding& encoding = {});

}  // namespace ts::raster
