#pragma once
// One file of a DemSource: its grid from its header, its cells read by windows. Internal to
// DemSource (dem_source.hpp).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>

#include "core/dem/block_cache.hpp"
#include "core/dem/dem_layout.hpp"

namespace ts::dem {

// Where a part's cells go: the window's heights and void flags at the first cell the part
// fills, `stride` cells from one row to the next.
struct WindowRows {
    float* z = nullptr;
    std::uint8_t* voids = nullptr;
    std::size_t stride = 0;
};

class DemPart {
public:
    virtual ~DemPart() = default;
    const DemLayout& layout() const { return layout_; }
    // Merges the part's cells [col0, col0 + cols) x [row0, row0 + rows), which lie inside it,
    // into `out` by mosaic's rule (merge_into). Decoded blocks come from and go to `cache`.
    // Thread-safe; throws ts::InputError if the file no longer reads.
    virtual void read(int col0, int row0, int cols, int rows, const WindowRows& out, BlockCache& cache) const = 0;

protected:
    DemLayout layout_;
};

// The part for `path`, reading its header only; the format is chosen as read_dem chooses it.
// `key` tells this part's blocks from other parts' in a shared cache. Throws ts::InputError
// "path: problem" as read_dem does.
std::unique_ptr<DemPart> open_dem_part(const std::filesystem::path& path, std::uint32_t key);
std::unique_ptr<DemPart> open_hgt_part(const std::filesystem::path& path);
std::unique_ptr<DemPart> open_hgt_zip_part(const std::filesystem::path& path, std::uint32_t key);
std::unique_ptr<DemPart> open_geotiff_part(const std::filesystem::path& path, std::uint32_t key);

// The cache key of block `block` of part `key`.
inline std::uint64_t block_key(std::uint32_t key, std::uint32_t block) { return std::uint64_t(key) << 32 | block; }

}  // namespace ts::dem
