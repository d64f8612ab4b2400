#include "core/dem/hgt_zip.hpp"

#include <cctype>

#include <zip.h>

#include "core/dem/hgt_format.hpp"
#include "core/util/error.hpp"

namespace ts::dem {

namespace {

// An archive open for reading, discarded (never written back) when it goes out of scope.
struct Archive {
    zip_t* zip = nullptr;
    explicit Archive(const std::string& source) {
        int err = 0;
        zip = zip_open(source.c_str(), ZIP_RDONLY, &err);
        if (!zip) throw input_error(source, "not a readable zip archive");
    }
    ~Archive() { zip_discard(zip); }
    Archive(const Archive&) = delete;
    Archive& operator=(const Archive&) = delete;
};

}  // namespace

HgtZipEntry find_hgt_zip_entry(const std::filesystem::path& path) {
    const std::string source = path.string();
    const Archive archive(source);
    const zip_int64_t n = zip_get_num_entries(archive.zip, 0);
    for (zip_int64_t i = 0; i < n; ++i) {
        zip_stat_t st;
        if (zip_stat_index(archive.zip, zip_uint64_t(i), 0, &st) != 0 || !(st.valid & ZIP_STAT_NAME)) continue;
        const std::string entry = st.name;
        std::string lower = entry;
        for (auto& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
        if (lower.size() < 4 || lower.compare(lower.size() - 4, 4, ".hgt") != 0) continue;
        HgtZipEntry found;
        found.index = std::uint64_t(i);
        found.where = source + " (" + entry + ")";
        if (!(st.valid & ZIP_STAT_SIZE)) throw input_error(found.where, "zip entry without a size");
        require_hgt_size(st.size, found.where);
        found.size = st.size;
        found.names = std::filesystem::path(entry).filename().string() + "|" + path.filename().string();
        return found;
    }
    throw input_error(source, "zip archive holds no .hgt file");
}

std::vector<unsigned char> inflate_hgt_zip_entry(const std::filesystem::path& path, const HgtZipEntry& entry) {
    const Archive archive(path.string());
    zip_file_t* f = zip_fopen_index(archive.zip, entry.index, 0);
    if (!f) throw input_error(entry.where, "cannot read the zip entry");
    std::vector<unsigned char> bytes(entry.size);
    const zip_int64_t got = zip_fread(f, bytes.data(), entry.size);
    zip_fclose(f);
    if (got < 0) throw input_error(entry.where, "corrupt zip entry");
    bytes.resize(std::size_t(got));
    return bytes;
}

}  // namespace ts::dem
