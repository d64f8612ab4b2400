#pragma once
// 8-bit PNG, encoded here: the rows filtered (PNG filter types 0-4), one zlib stream
// (core/raster/zlib_stream: ISA-L or libdeflate), and the IHDR / IDAT / IEND chunks with their
// CRCs. Every PNG terrashade writes (rendered frames, hillshade and svf quick-looks) goes
// through write_png.
//
// Why not libpng + zlib: for a 500x500 rendered frame libpng with zlib at level 3 took 2.6x
// the CPU time of this encoder and gave a file 1-8% larger (hillshades: 2.1x, 11%; see
// docs/dependencies.md, "PNG output"), and a sequence of frames is encoder-bound. Why not
// OpenImageIO: linking it pulls ~260 shared libraries whose symbol resolution cost every
// terrashade run 0.3 s at start-up.
//
// Memory: the filtered rows (width * channels + 1 bytes per row) and the compressed stream are
// whole buffers beside the caller's pixels (the deflater compresses a buffer at once).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/raster/zlib_stream.hpp"

namespace ts::raster {

// The PNG filter applied to every row (the PNG specification, section 9; the values are the
// filter-type bytes).
enum class PngFilter : std::uint8_t {
    none = 0,     // the bytes as they are
    sub = 1,      // minus the same channel of the pixel on the left
    up = 2,       // minus the byte above
    average = 3,  // minus the floor of the mean of left and above
    paeth = 4,    // minus whichever of left, above, upper-left is closest to left + above - upper-left
    // Per picture: whichever of none, sub and paeth compresses a sample of the rows smallest
    // (8-row bands every 256 rows, ~3% of the picture, compressed once per filter).
    trial = 255,
};

// How the pixels are compressed. The defaults were measured on 500x500 rendered maps, 640x360
// and 960x540 perspective views and hillshade / svf quick-looks: the best filter depends on the
// picture (none for maps, whose flat areas repeat whole pixels; sub for hazy perspective views;
// paeth for hillshades) and the trial found it on all but one of 20 such pictures (that one
// 1.1% larger). ISA-L level 1 encodes a map frame in about a third of libdeflate level 1's time
// for a file ~7% larger; libdeflate level 2 makes it ~9% smaller than libdeflate level 1 for
// 1.4x that time (docs/dependencies.md, "PNG output").
struct PngEncoding {
    Deflater deflater = Deflater::isal;
    int level = 1;  // 0..max_level(deflater)
    PngFilter filter = PngFilter::trial;
};

// The PNG file's bytes for width x height pixels of 1 (grey), 2 (grey + alpha), 3 (RGB) or 4
// (RGBA) interleaved 8-bit channels, row-major from the top row. Deterministic: the same pixels
// and encoding give the same bytes on any thread of one machine (map tiles and their resume rely
// on it; ISA-L picks its kernels by CPU model, libdeflate's output does not depend on it). Throws
// ts::InputError naming `shown_path` on bad arguments.
std::vector<std::uint8_t> encode_png(int width, int height, int channels, const std::uint8_t* data,
                                     const PngEncoding& encoding = {}, const std::string& shown_path = "PNG");

// Writes width x height pixels of 1 (grey), 2 (grey + alpha), 3 (RGB) or 4 (RGBA) interleaved 8-bit channels,
// row-major from the top row. Not atomic by itself: callers go through write_atomically.
// Throws ts::InputError naming `shown_path` on failure.
void write_png(const std::filesystem::path& file, const std::filesystem::path& shown_path, int width, int height,
               int channels, const std::uint8_t* data, const PngEncoding& encoding = {});

}  // namespace ts::raster
