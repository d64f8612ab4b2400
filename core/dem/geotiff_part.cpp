// GeoTIFF parts of a DemSource: only the strips or tiles a window touches are decoded, each
// into the cache. A libtiff handle decodes one block at a time, so concurrent reads each
// borrow a handle of their own from a small pool (opened on demand, a few kept idle).
#include <algorithm>
#include <mutex>
#include <optional>
#include <vector>

#include "core/dem/dem_part.hpp"
#include "core/dem/geotiff_header.hpp"
#include "core/dem/mosaic.hpp"

namespace ts::dem {

namespace {

class TiffHandles {
public:
    // Without memory mapping ('m'): handles live as long as the source, and a mapped file cut
    // short meanwhile would fault (SIGBUS) where a read gives an error.
    static constexpr const char* kMode = "rm";

    TiffHandles(std::filesystem::path path, std::unique_ptr<raster::TiffFile> first) : path_(std::move(path)) {
        idle_.push_back(std::move(first));
    }

    // A handle for this thread alone, back in the pool when the lease ends.
    class Lease {
    public:
        Lease(TiffHandles& pool, std::unique_ptr<raster::TiffFile> file) : pool_(pool), file_(std::move(file)) {}
        ~Lease() { pool_.give_back(std::move(file_)); }
        Lease(const Lease&) = delete;
        Lease& operator=(const Lease&) = delete;
        const raster::TiffFile& file() const { return *file_; }

    private:
        TiffHandles& pool_;
        std::unique_ptr<raster::TiffFile> file_;
    };

    Lease borrow() {
        {
            std::lock_guard lock(mutex_);
            if (!idle_.empty()) {
                std::unique_ptr<raster::TiffFile> file = std::move(idle_.back());
                idle_.pop_back();
                return Lease(*this, std::move(file));
            }
        }
        return Lease(*this, std::make_unique<raster::TiffFile>(path_, kMode));
    }

private:
    // Idle handles kept open: enough for a few reading threads, and few file descriptors for
    // a mosaic of many files.
    static constexpr std::size_t kMaxIdle = 2;

    void give_back(std::unique_ptr<raster::TiffFile> file) {
        std::lock_guard lock(mutex_);
        if (idle_.size() < kMaxIdle) idle_.push_back(std::move(file));
    }

    std::filesystem::path path_;
    std::mutex mutex_;
    std::vector<std::unique_ptr<raster::TiffFile>> idle_;
};

class GeoTiffPart final : public DemPart {
public:
    GeoTiffPart(const std::filesystem::path& path, std::uint32_t key) : key_(key) {
        auto file = std::make_unique<raster::TiffFile>(path, TiffHandles::kMode);
        header_ = read_geotiff_header(*file, std::uint64_t(-1));
        layout_ = header_.layout;
        decoder_.emplace(header_.type, header_.nodata, header_.metres_per_unit);
        handles_ = std::make_unique<TiffHandles>(path, std::move(file));
    }

    void read(int col0, int row0, int cols, int rows, const WindowRows& out, BlockCache& cache) const override {
        const TiffBlocks& b = header_.blocks;
        const std::uint32_t bx0 = std::uint32_t(col0) / b.block_w, bx1 = std::uint32_t(col0 + cols - 1) / b.block_w;
        const std::uint32_t by0 = std::uint32_t(row0) / b.block_h, by1 = std::uint32_t(row0 + rows - 1) / b.block_h;
        const std::size_t sample_size = std::size_t(decoder_->sample_size());
        std::vector<float> z;
        std::vector<std::uint8_t> voids;
        for (std::uint32_t by = by0; by <= by1; ++by)
            for (std::uint32_t bx = bx0; bx <= bx1; ++bx) {
                const std::uint32_t i = by * b.across + bx;
                const BlockCache::Block block = cache.get(block_key(key_, i), [&] { return decode(i); });
                // The window's cells in this block.
                const GeoTiffHeader::Cells c = header_.cells(i);
                const int c0 = std::max(col0, c.col0), c1 = std::min(col0 + cols, c.col0 + c.cols);
                const int r0 = std::max(row0, c.row0), r1 = std::min(row0 + rows, c.row0 + c.rows);
                const auto n = std::size_t(c1 - c0);
                z.resize(n);
                voids.resize(n);
                for (int r = r0; r < r1; ++r) {
                    if (block->empty()) {
                        decoder_->decode_sparse(n, z.data(), voids.data());
                    } else {
                        const std::size_t at = (std::size_t(r - c.row0) * b.block_w + std::size_t(c0 - c.col0)) * sample_size;
                        decoder_->decode(block->data() + at, n, z.data(), voids.data());
                    }
                    const std::size_t to = std::size_t(r - row0) * out.stride + std::size_t(c0 - col0);
                    merge_into(z.data(), voids.data(), out.z + to, out.voids + to, n);
                }
            }
    }

private:
    // Block i's samples as libtiff decodes them; no bytes for a sparse block.
    std::vector<std::uint8_t> decode(std::uint32_t i) const {
        const TiffHandles::Lease lease = handles_->borrow();
        std::vector<std::uint8_t> bytes(header_.decoded_bytes(i));
        if (!read_geotiff_block(lease.file(), header_, i, bytes.data())) return {};
        return bytes;
    }

    std::uint32_t key_;
    GeoTiffHeader header_;
    std::optional<SampleDecoder> decoder_;  // set once the header is read
    std::unique_ptr<TiffHandles> handles_;
};

}  // namespace

std::unique_ptr<DemPart> open_geotiff_part(const std::filesystem::path& path, std::uint32_t key) {
    return std::make_unique<GeoTiffPart>(path, key);
}

}  // namespace ts::dem
