#pragma once
// An open TIFF with the GeoTIFF tags registered, whose libtiff errors and warnings are kept
// (not printed): a bad file must give one line on stderr, naming the file, from our code.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <tiffio.h>

namespace ts::raster {

// Registers the GeoTIFF tags and GDAL's GDAL_METADATA / GDAL_NODATA with libtiff (once per
// process; TiffFile calls it). Code that opens TIFFs itself (tests) calls it first.
void register_tiff_tags();

class TiffFile {
public:
    // mode "r" or "w"/"w8" as TIFFOpen. Reading errors throw ts::InputError "path: problem".
    TiffFile(const std::filesystem::path& path, const char* mode);
    ~TiffFile();
    TiffFile(const TiffFile&) = delete;
    TiffFile& operator=(const TiffFile&) = delete;

    TIFF* get() const { return tif_; }
    const std::string& path() const { return path_; }
    // libtiff's last error message for this file ("" if none).
    const std::string& last_error() const { return *last_error_; }
    // libtiff's warnings for this file so far, "module: message", at most 64.
    const std::vector<std::string>& warnings() const { return *warnings_; }
    // Flushes and closes; throws ts::InputError if libtiff reports a write error.
    void close();

private:
    std::string path_;
    std::unique_ptr<std::string> last_error_;  // heap: libtiff keeps a pointer to it
    std::unique_ptr<std::vector<std::string>> warnings_;  // likewise
    TIFF* tif_ = nullptr;
};

}  // namespace ts::raster
