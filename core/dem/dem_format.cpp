#include "core/dem/dem_format.hpp"

#include <array>
#include <cctype>
#include <fstream>
#include <string>
#include <system_error>

#include "core/util/error.hpp"

namespace ts::dem {

DemFormat dem_format(const std::filesystem::path& path) {
    const std::string source = path.string();
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) throw input_error(source, "no such file");
    if (std::filesystem::is_directory(status)) throw input_error(source, "is a directory, not a DEM file");
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) throw input_error(source, "cannot read (" + ec.message() + ")");
    if (size == 0) throw input_error(source, "empty file");

    std::array<unsigned char, 4> magic{};
    {
        std::ifstream in(path, std::ios::binary);
        if (!in) throw input_error(source, "cannot open (permission denied?)");
        in.read(reinterpret_cast<char*>(magic.data()), magic.size());
    }
    const bool tiff = (magic[0] == 'I' && magic[1] == 'I' && (magic[2] == 42 || magic[2] == 43) && magic[3] == 0) ||
                      (magic[0] == 'M' && magic[1] == 'M' && magic[2] == 0 && (magic[3] == 42 || magic[3] == 43));
    if (tiff) return DemFormat::geotiff;
    if (magic[0] == 'P' && magic[1] == 'K' && magic[2] == 3 && magic[3] == 4) return DemFormat::hgt_zip;

    // .hgt has no header: recognised by its name and exact size (its reader explains a mismatch).
    std::string ext = path.extension().string();
    for (auto& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".hgt") return DemFormat::hgt;
    if (size == 2884802 || size == 25934402) return DemFormat::hgt;
    throw input_error(source, "unrecognised DEM format (expected GeoTIFF, SRTM .hgt or .hgt.zip)");
}

}  // namespace ts::dem
