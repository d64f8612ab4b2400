// .hgt and .hgt.zip parts of a DemSource. A plain .hgt is read row by row at its offsets
// (pread: no shared file position, so reads need no lock); a zip entry cannot be entered
// mid-stream, so it is inflated whole once and kept in the cache as one block.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

#include "core/dem/dem_part.hpp"
#include "core/dem/hgt_format.hpp"
#include "core/dem/hgt_zip.hpp"
#include "core/dem/mosaic.hpp"
#include "core/util/error.hpp"

namespace ts::dem {

namespace {

// Decodes `cols` big-endian samples per row, rows `row_bytes(r)` gives, into `out`.
template <typename RowBytes>
void merge_hgt_rows(int cols, int rows, const WindowRows& out, RowBytes row_bytes) {
    const auto n = std::size_t(cols);
    std::vector<float> z(n);
    std::vector<std::uint8_t> voids(n);
    for (int r = 0; r < rows; ++r) {
        decode_hgt_heights(row_bytes(r), z.size(), z.data(), voids.data());
        const std::size_t at = std::size_t(r) * out.stride;
        merge_into(z.data(), voids.data(), out.z + at, out.voids + at, z.size());
    }
}

class HgtPart final : public DemPart {
public:
    explicit HgtPart(const std::filesystem::path& path) : path_(path) {
        const std::string source = path.string();
        std::error_code ec;
        const std::uint64_t size = std::filesystem::file_size(path, ec);
        if (ec) throw input_error(source, "cannot read (" + ec.message() + ")");
        require_hgt_size(size, source);
        side_ = hgt_side(size);
        layout_ = hgt_layout(side_, path.filename().string(), source);
    }

    void read(int col0, int row0, int cols, int rows, const WindowRows& out, BlockCache&) const override {
        const std::string& source = layout_.source;
        struct File {
            int fd;
            ~File() {
                if (fd >= 0) ::close(fd);
            }
        } file{::open(path_.c_str(), O_RDONLY | O_CLOEXEC)};
        if (file.fd < 0) throw input_error(source, std::string("cannot open (") + std::strerror(errno) + ")");
        std::vector<unsigned char> bytes(std::size_t(cols) * 2);
        merge_hgt_rows(cols, rows, out, [&](int r) {
            const off_t at = off_t((std::int64_t(row0 + r) * side_ + col0) * 2);
            std::size_t got = 0;
            while (got < bytes.size()) {
                const ssize_t n = ::pread(file.fd, bytes.data() + got, bytes.size() - got, at + off_t(got));
                if (n < 0 && errno == EINTR) continue;
                if (n <= 0)
                    throw input_error(source, n < 0 ? "cannot read (" + std::string(std::strerror(errno)) + ")"
                                                    : "truncated while being read: row " + std::to_string(row0 + r) + " is missing");
                got += std::size_t(n);
            }
            return bytes.data();
        });
    }

private:
    std::filesystem::path path_;
    int side_ = 0;
};

class HgtZipPart final : public DemPart {
public:
    HgtZipPart(const std::filesystem::path& path, std::uint32_t key)
        : path_(path), key_(key), entry_(find_hgt_zip_entry(path)) {
        layout_ = hgt_layout(hgt_side(entry_.size), entry_.names, entry_.where);
        layout_.source = path.string();
    }

    void read(int col0, int row0, int cols, int rows, const WindowRows& out, BlockCache& cache) const override {
        const BlockCache::Block tile = cache.get(block_key(key_, 0), [&] {
            std::vector<unsigned char> bytes = inflate_hgt_zip_entry(path_, entry_);
            require_hgt_size(bytes.size(), entry_.where);  // fewer bytes than the directory said
            return bytes;
        });
        const std::size_t side = std::size_t(layout_.width);
        merge_hgt_rows(cols, rows, out, [&](int r) {
            return tile->data() + (std::size_t(row0 + r) * side + std::size_t(col0)) * 2;
        });
    }

private:
    std::filesystem::path path_;
    std::uint32_t key_;
    HgtZipEntry entry_;
};

}  // namespace

std::unique_ptr<DemPart> open_hgt_part(const std::filesystem::path& path) { return std::make_unique<HgtPart>(path); }

std::unique_ptr<DemPart> open_hgt_zip_part(const std::filesystem::path& path, std::uint32_t key) {
    return std::make_unique<HgtZipPart>(path, key);
}

}  // namespace ts::dem
