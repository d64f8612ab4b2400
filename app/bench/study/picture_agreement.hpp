#pragma once
// A picture against a reference picture of the same crop (Blender Cycles'): the luminance of the
// inner texels (the crop's border is open ground for Cycles' mesh, where the DEM goes on), their
// correlation, relative RMSE and bias. Header-only, so that `bench bounce` and the Cycles CLI
// test (tests/cli/cycles_reference_cli_test.cpp) measure alike without linking the bench.
#include <cmath>
#include <cstddef>
#include <vector>

namespace ts::bench {

// Rec. 709 luminance of the texels at least `border` from the edge, row by row; rgb interleaved.
inline std::vector<double> inner_luminance(int width, int height, const float* rgb, int border) {
    std::vector<double> y;
    for (int r = border; r < height - border; ++r)
        for (int c = border; c < width - border; ++c) {
            const float* p = rgb + (std::size_t(r) * std::size_t(width) + std::size_t(c)) * 3;
            y.push_back(0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]);
        }
    return y;
}

struct PictureAgreement {
    double correlation = 0, relative_rmse = 0, bias = 0;  // the last two relative to the reference's mean
};

inline PictureAgreement picture_agreement(const std::vector<double>& reference, const std::vector<double>& mine) {
    const double n = double(reference.size());
    double mr = 0, mm = 0;
    for (std::size_t i = 0; i < reference.size(); ++i) mr += reference[i], mm += mine[i];
    mr /= n, mm /= n;
    double srm = 0, srr = 0, smm = 0, se = 0;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        const double dr = reference[i] - mr, dm = mine[i] - mm, e = mine[i] - reference[i];
        srm += dr * dm, srr += dr * dr, smm += dm * dm, se += e * e;
    }
    return {srm / std::sqrt(srr * smm), std::sqrt(se / n) / mr, (mm - mr) / mr};
}

}  // namespace ts::bench
