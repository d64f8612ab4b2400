#pragma once
// GeoTIFF samples -> heights: int8..int32, uint8..uint32 and float32/64 become float metres;
// GDAL_NODATA, NaN, +-Inf and values beyond float's range become voids. One definition for
// the whole-file reader (read_geotiff) and the window reader (DemSource).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace ts::dem {

enum class SampleType { u8, i8, u16, i16, u32, i32, f32, f64 };

// From the TIFF's SampleFormat and BitsPerSample; throws ts::InputError "path: ..." for a
// type no DEM uses (complex, 64-bit integers, odd bit widths).
SampleType sample_type(std::uint16_t format, std::uint16_t bits, const std::string& path);
int sample_bytes(SampleType type);

class SampleDecoder {
public:
    // `metres_per_unit`: heights stored in feet come out in metres (nodata compares first).
    SampleDecoder(SampleType type, std::optional<double> nodata, double metres_per_unit = 1.0);
    int sample_size() const { return sample_bytes(type_); }
    // `n` consecutive samples (host byte order, as libtiff decodes them) -> heights; voids NaN
    // with `voids` 1, else 0.
    void decode(const std::uint8_t* samples, std::size_t n, float* z, std::uint8_t* voids) const;
    // The `n` cells of a sparse block (no bytes, as GDAL writes with SPARSE_OK=TRUE) hold what
    // GDAL specifies: the nodata value, so voids, when the file has one, else zeros (GDAL
    // leaves out an all-zero block then).
    void decode_sparse(std::size_t n, float* z, std::uint8_t* voids) const;

private:
    SampleType type_;
    std::optional<double> nodata_;
    float nodata_single_;
    double metres_per_unit_;
};

}  // namespace ts::dem
