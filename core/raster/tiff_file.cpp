#include "core/raster/tiff_file.hpp"

#include <cstdarg>
#include <cstdio>
#include <mutex>

#include <xtiffio.h>

#include "core/util/error.hpp"

namespace ts::raster {

namespace {

int keep_error(TIFF*, void* user_data, const char* module, const char* fmt, va_list ap) {
    char buffer[512];
    std::vsnprintf(buffer, sizeof buffer, fmt, ap);
    auto* out = static_cast<std::string*>(user_data);
    *out = (module && *module ? std::string(module) + ": " : std::string()) + buffer;
    return 1;  // handled: libtiff must not print it
}

int drop_warning(TIFF*, void*, const char*, const char*, va_list) { return 1; }

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
    : path_(path.string()), last_error_(std::make_unique<std::string>()) {
    register_tiff_tags();

    TIFFOpenOptions* options = TIFFOpenOptionsAlloc();
    TIFFOpenOptionsSetErrorHandlerExtR(options, keep_error, last_error_.get());
    TIFFOpenOptionsSetWarningHandlerExtR(options, drop_warning, nullptr);
    tif_ = TIFFOpenExt(path_.c_str(), mode, options);
    TIFFOpenOptionsFree(options);
    if (!tif_) {
        const std::string why = last_error_->empty() ? "cannot open as TIFF" : "not a readable TIFF (" + *last_error_ + ")";
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
