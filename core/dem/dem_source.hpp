#pragma once
// A DEM read by windows: one or more files opened by their headers only, placed on one grid
// as mosaic(read_dem(...)) places them, and any window of that grid decoded on demand. For
// DEMs larger than memory (the flythrough streams tiles from it): only the blocks a window
// touches are decoded, and decoded blocks are kept in a bounded cache (block_cache.hpp).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "core/dem/dem_layout.hpp"

namespace ts::dem {

class DemSource {
public:
    // Reads only headers (GeoTIFF tags and georeferencing, .hgt name and byte count, the zip's
    // directory). Throws ts::InputError "path: problem" as read_dem/mosaic do (missing,
    // truncated, mislabelled file, mosaic mismatch). `cache_bytes` bounds the decoded data kept
    // between reads (e.g. an .hgt.zip's inflated entry, decoded TIFF strips/tiles).
    explicit DemSource(const std::vector<std::filesystem::path>& paths, std::size_t cache_bytes = std::size_t(256) << 20);
    ~DemSource();
    DemSource(const DemSource&) = delete;
    DemSource& operator=(const DemSource&) = delete;

    const DemLayout& layout() const;

    // Heights of the window [col0, col0 + width) x [row0, row0 + height) of the grid, row-major,
    // metres; voids (nodata, NaN, uncovered cells) NaN, and `voids` (if given) 1 there, else 0.
    // The window must lie inside the grid (std::invalid_argument otherwise). Thread-safe.
    // Throws ts::InputError if a file no longer reads as its header said (truncated since).
    void read(int col0, int row0, int width, int height, std::vector<float>& z,
              std::vector<std::uint8_t>* voids = nullptr) const;

    // Decoded bytes held in the cache now, and the most ever held.
    std::size_t cached_bytes() const;
    std::size_t peak_cached_bytes() const;
    // Blocks decoded so far (GeoTIFF strips or tiles, inflated zip entries; plain .hgt rows
    // are read, not decoded): what reads have cost beyond the cache.
    std::uint64_t decoded_blocks() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace ts::dem
