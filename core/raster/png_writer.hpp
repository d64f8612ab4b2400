#pragma once
// 8-bit PNG through libpng's simplified API. Kept apart from OpenImageIO on purpose: linking
// OIIO pulls ~260 shared libraries whose symbol resolution cost every terrashade run 0.3 s at
// start-up (perf: 70% in the dynamic loader), more than the shading itself.
#include <cstdint>
#include <filesystem>

namespace ts::raster {

// Writes width x height pixels of 1 (grey), 3 (RGB) or 4 (RGBA) interleaved 8-bit channels,
// row-major from the top row. Not atomic by itself: callers go through write_atomically.
// Throws ts::InputError naming `shown_path` on failure.
void write_png(const std::filesystem::path& file, const std::filesystem::path& shown_path, int width, int height,
               int channels, const std::uint8_t* data);

}  // namespace ts::raster
