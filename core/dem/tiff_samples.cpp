#include "core/dem/tiff_samples.hpp"

#include <cmath>
#include <cstring>
#include <limits>

#include <tiffio.h>

#include "core/util/error.hpp"

namespace ts::dem {

namespace {

template <typename T>
double load(const std::uint8_t* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return double(v);
}

double sample_value(SampleType t, const std::uint8_t* p) {
    switch (t) {
        case SampleType::u8: return load<std::uint8_t>(p);
        case SampleType::i8: return load<std::int8_t>(p);
        case SampleType::u16: return load<std::uint16_t>(p);
        case SampleType::i16: return load<std::int16_t>(p);
        case SampleType::u32: return load<std::uint32_t>(p);
        case SampleType::i32: return load<std::int32_t>(p);
        case SampleType::f32: return load<float>(p);
        case SampleType::f64: return load<double>(p);
    }
    return 0;
}

// A height the DEM can hold: finite and within float's range. NaN, +-Inf and float64 values
// beyond +-3.4e38 are no heights at all (and the last would be undefined as a float).
bool is_height(double v) { return std::abs(v) <= double(std::numeric_limits<float>::max()); }

}  // namespace

SampleType sample_type(std::uint16_t format, std::uint16_t bits, const std::string& path) {
    if (format == SAMPLEFORMAT_IEEEFP && bits == 32) return SampleType::f32;
    if (format == SAMPLEFORMAT_IEEEFP && bits == 64) return SampleType::f64;
    const bool is_signed = format == SAMPLEFORMAT_INT;
    if (format == SAMPLEFORMAT_UINT || format == SAMPLEFORMAT_INT || format == SAMPLEFORMAT_VOID) {
        switch (bits) {
            case 8: return is_signed ? SampleType::i8 : SampleType::u8;
            case 16: return is_signed ? SampleType::i16 : SampleType::u16;
            case 32: return is_signed ? SampleType::i32 : SampleType::u32;
            default: break;
        }
    }
    throw input_error(path, "unsupported TIFF sample type (" + std::to_string(bits) + "-bit, format " +
                                std::to_string(format) + "); a DEM needs 8/16/32-bit integers or 32/64-bit floats");
}

int sample_bytes(SampleType t) {
    switch (t) {
        case SampleType::u8: case SampleType::i8: return 1;
        case SampleType::u16: case SampleType::i16: return 2;
        case SampleType::u32: case SampleType::i32: case SampleType::f32: return 4;
        case SampleType::f64: return 8;
    }
    return 1;
}

// Nodata compares in the sample's own precision (a float32 file's 9999 is 9999.0f); a nodata
// value no float can hold matches no float32 sample.
SampleDecoder::SampleDecoder(SampleType type, std::optional<double> nodata, double metres_per_unit)
    : type_(type),
      nodata_(nodata),
      nodata_single_(nodata && is_height(*nodata) ? float(*nodata) : std::numeric_limits<float>::quiet_NaN()),
      metres_per_unit_(metres_per_unit) {}

void SampleDecoder::decode(const std::uint8_t* samples, std::size_t n, float* z, std::uint8_t* voids) const {
    const std::size_t bytes = std::size_t(sample_size());
    const bool single = type_ == SampleType::f32;
    for (std::size_t i = 0; i < n; ++i) {
        const double v = sample_value(type_, samples + i * bytes);
        bool is_void = !is_height(v);
        if (nodata_ && !is_void) is_void = single ? float(v) == nodata_single_ : v == *nodata_;
        z[i] = is_void ? std::numeric_limits<float>::quiet_NaN() : float(v * metres_per_unit_);
        voids[i] = is_void ? 1 : 0;
    }
}

void SampleDecoder::decode_sparse(std::size_t n, float* z, std::uint8_t* voids) const {
    const bool is_void = nodata_.has_value();
    for (std::size_t i = 0; i < n; ++i) {
        z[i] = is_void ? std::numeric_limits<float>::quiet_NaN() : 0.0f;
        voids[i] = is_void ? 1 : 0;
    }
}

}  // namespace ts::dem
