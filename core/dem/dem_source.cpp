#include "core/dem/dem_source.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/dem/block_cache.hpp"
#include "core/dem/dem_part.hpp"
#include "core/dem/mosaic.hpp"
#include "core/util/error.hpp"

namespace ts::dem {

struct DemSource::Impl {
    explicit Impl(std::size_t cache_bytes) : cache(cache_bytes) {}
    std::vector<std::unique_ptr<DemPart>> parts;
    MosaicPlan plan;
    mutable BlockCache cache;
};

DemSource::DemSource(const std::vector<std::filesystem::path>& paths, std::size_t cache_bytes)
    : impl_(std::make_unique<Impl>(cache_bytes)) {
    if (paths.empty()) throw InputError("no DEM given");
    if (paths.size() > std::numeric_limits<std::uint32_t>::max()) throw InputError("too many DEM files");
    std::vector<DemLayout> layouts;
    for (std::size_t k = 0; k < paths.size(); ++k) {
        impl_->parts.push_back(open_dem_part(paths[k], std::uint32_t(k)));
        layouts.push_back(impl_->parts.back()->layout());
    }
    impl_->plan = plan_mosaic(layouts);
}

DemSource::~DemSource() = default;

const DemLayout& DemSource::layout() const { return impl_->plan.layout; }

void DemSource::read(int col0, int row0, int width, int height, std::vector<float>& z,
                     std::vector<std::uint8_t>* voids) const {
    const DemLayout& grid = impl_->plan.layout;
    if (col0 < 0 || row0 < 0 || width < 0 || height < 0 || std::int64_t(col0) + width > grid.width ||
        std::int64_t(row0) + height > grid.height)
        throw std::invalid_argument("DemSource::read: window " + std::to_string(width) + "x" + std::to_string(height) +
                                    " at (" + std::to_string(col0) + ", " + std::to_string(row0) + ") is not inside the " +
                                    std::to_string(grid.width) + "x" + std::to_string(grid.height) + " grid of " +
                                    grid.source);
    const std::size_t n = std::size_t(width) * std::size_t(height);
    z.assign(n, std::numeric_limits<float>::quiet_NaN());
    std::vector<std::uint8_t> own_voids;  // the merge needs the flags even when the caller does not
    std::vector<std::uint8_t>& flags = voids ? *voids : own_voids;
    flags.assign(n, 1);
    for (std::size_t k = 0; k < impl_->parts.size(); ++k) {
        const DemPart& part = *impl_->parts[k];
        const auto [pc, pr] = impl_->plan.offsets[k];
        // The window's cells this part covers, in grid cells.
        const int c0 = std::max(col0, pc), c1 = std::min(col0 + width, pc + part.layout().width);
        const int r0 = std::max(row0, pr), r1 = std::min(row0 + height, pr + part.layout().height);
        if (c0 >= c1 || r0 >= r1) continue;
        const std::size_t at = std::size_t(r0 - row0) * std::size_t(width) + std::size_t(c0 - col0);
        part.read(c0 - pc, r0 - pr, c1 - c0, r1 - r0, {z.data() + at, flags.data() + at, std::size_t(width)},
                  impl_->cache);
    }
}

std::size_t DemSource::cached_bytes() const { return impl_->cache.bytes(); }
std::size_t DemSource::peak_cached_bytes() const { return impl_->cache.peak_bytes(); }
std::uint64_t DemSource::decoded_blocks() const { return impl_->cache.decodes(); }

}  // namespace ts::dem
