// SRTM .hgt and .hgt.zip read whole into a Dem (the format: hgt_format.hpp).
#include <fstream>

#include "core/dem/decode_limits.hpp"
#include "core/dem/hgt_format.hpp"
#include "core/dem/hgt_zip.hpp"
#include "core/dem/read_dem.hpp"
#include "core/util/error.hpp"

namespace ts::dem {

namespace {

Dem decode_hgt(const unsigned char* bytes, std::size_t size, const std::string& name, const std::string& source) {
    require_hgt_size(size, source);
    const int side = hgt_side(size);
    require_memory_for(source, "decoding", std::uint64_t(side), std::uint64_t(side));
    Dem dem = allocate_dem(hgt_layout(side, name, source));
    decode_hgt_heights(bytes, dem.z.size(), dem.z.data(), dem.void_mask.data());
    return dem;
}

}  // namespace

Dem read_hgt_bytes(const std::string& bytes, const std::string& name, const std::string& source) {
    return decode_hgt(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), name, source);
}

Dem read_hgt(const std::filesystem::path& path) {
    const std::string source = path.string();
    std::error_code ec;
    const std::uint64_t size = std::filesystem::file_size(path, ec);
    if (ec) throw input_error(source, "cannot read (" + ec.message() + ")");
    require_hgt_size(size, source);  // a mislabelled multi-gigabyte file is not read first
    std::ifstream in(path, std::ios::binary);
    if (!in) throw input_error(source, "cannot open");
    std::string bytes(std::size_t(size), '\0');
    in.read(bytes.data(), std::streamsize(bytes.size()));
    bytes.resize(std::size_t(in.gcount()));  // shrank while read: decode_hgt says so
    return read_hgt_bytes(bytes, path.filename().string(), source);
}

Dem read_hgt_zip(const std::filesystem::path& path) {
    const HgtZipEntry entry = find_hgt_zip_entry(path);
    const std::vector<unsigned char> bytes = inflate_hgt_zip_entry(path, entry);
    Dem dem = decode_hgt(bytes.data(), bytes.size(), entry.names, entry.where);
    dem.source = path.string();
    return dem;
}

}  // namespace ts::dem
