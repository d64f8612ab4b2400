#include "core/raster/tiff_file.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <mutex>

#include <xtiffio.h>

#include "core/util/error.hpp"
#include "core/util/memory.hpp"

namespace ts::raster {

namespace {

int keep_error(TIFF*, void* user_data, const char* module, const char* fmt, va_list ap) {
    char buffer[512];
    std::vsnprintf(buffer, sizeof buffer, fmt, ap);
    auto* out = static_cast<std::string*>(user_data);
    *out = (module && *module ? std::string(module) + ": " : std::string()) + buffer;
    return 1;  // handled: libtiff must not print it
}

// Warnings are kept, not printed: most are noise (GeoTIFF tags libtiff itself does not know),
// but some tell a reader that libtiff repaired a corrupt header (TiffFile::warnings()).
int keep_warning(TIFF*, void* user_data, const char* module, const char* fmt, va_list ap) {
    auto* out = static_cast<std::vector<std::string>*>(user_data);
    if (out->size() >= 64) return 1;  // a corrupt file can warn once per tag
    char buffer[512];
    std::vsnprintf(buffer, sizeof buffer, fmt, ap);
    out->push_back((module && *module ? std::string(module) + ": " : std::string()) + buffer);
    return 1;
}

// GDAL's private tags as GDAL itself declares them (plain ASCII, no count argument); libtiff
// would otherwise register them as anonymous fields with a different calling convention.
const TIFFFieldInfo kGdalTags[] = {
    {TIFFTAG_GDAL_METADATA, -1, -1, TIFF_ASCII, FIELD_CUSTOM, 1, 0, const_cast<char*>("GDALMetadata")},
    {TIFFTAG_GDAL_NODATA, -1, -1, TIFF_ASCII, FIELD_CUSTOM, 1, 0, const_cast<char*>("GDALNoDataValue")},
};

TIFFExtendProc g_parent_extender = nullptr;  // set once under std::call_once, then read-only

void extend_tags(TIFF* tif) {
    TIFFMergeFieldInfo(tif, kGdalTags, sizeof kGdalTags / sizeof kGdalTags[0]);
    if (g_parent_extender) g_parent_extender(tif);
}

}  // namespace

void register_tiff_tags() {
    static std::once_flag once;
    std::call_once(once, [] {
        XTIFFInitialize();
        g_parent_extender = TIFFSetTagExtender(extend_tags);
    });
}

TiffFile::TiffFile(const std::filesystem::path& path, const char* mode)
    : path_(path.string()),
      last_error_(std::make_unique<std::string>()),
      warnings_(std::make_unique<std::vector<std::string>>()) {
    register_tiff_tags();

    TIFFOpenOptions* options = TIFFOpenOptionsAlloc();
    TIFFOpenOptionsSetErrorHandlerExtR(options, keep_error, last_error_.get());
    TIFFOpenOptionsSetWarningHandlerExtR(options, keep_warning, warnings_.get());
    // No single libtiff allocation (tag arrays, codec buffers) larger than the memory there is:
    // a corrupt count then fails as an error instead of swapping or being OOM-killed.
    if (mode[0] == 'r')
        TIFFOpenOptionsSetMaxSingleMemAlloc(
            options, tmsize_t(std::min<std::uint64_t>(available_memory(), std::uint64_t(std::numeric_limits<tmsize_t>::max()))));
    tif_ = TIFFOpenExt(path_.c_str(), mode, options);
    TIFFOpenOptionsFree(options);
    if (!tif_) {
        const bool reading = mode[0] == 'r';
        const std::string why = last_error_->empty() ? (reading ? "cannot open as TIFF" : "cannot write a TIFF there")
                                : reading          ? "not a readable TIFF (" + *last_error_ + ")"
                                                   : "cannot write (" + *last_error_ + ")";
        throw input_error(path_, why);
    }
}

void TiffFile::close() {
    if (!tif_) return;
    TIFF* tif = tif_;
    tif_ = nullptr;
    TIFFClose(tif);
    if (!last_error_->empty()) throw input_error(path_, "writing TIFF failed: " + *last_error_);
}

TiffFile::~TiffFile() {
    if (tif_) TIFFClose(tif_);
}

}  // namespace ts::raster
