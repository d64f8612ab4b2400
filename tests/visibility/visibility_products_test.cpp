#include "core/util/angles.hpp"
#include "core/visibility/visibility_products.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/sh/sh_basis.hpp"
#include "core/sh/sh_shared.hpp"
#include "core/util/error.hpp"
#include "core/visibility/sky_integrals.hpp"

using namespace ts::visibility;
using ts::kPi;

namespace {


// Horizons that exercise every branch of the per-texel formulas: random angles over the whole
// [-pi/2, pi/2], horizons below 0 all round, wedges crossing 0, ends exactly at 0, equal and
// nearly equal neighbours, the extremes +-pi/2, and void receivers (one NaN azimuth).
HorizonSet awkward_set(int width, int height, int directions) {
    HorizonSet set;
    set.width = width;
    set.height = height;
    set.directions = directions;
    set.angle.resize(set.texels() * std::size_t(directions));
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> any(float(-kPi / 2), float(kPi / 2));
    std::uniform_real_distribution<float> small(-0.05f, 0.05f);
    for (std::size_t t = 0; t < set.texels(); ++t) {
        const int kind = int(t % 8);
        const float base = any(rng);
        for (int d = 0; d < directions; ++d) {
            float v = 0;
            switch (kind) {
                case 0:
                    v = any(rng);
                    break;
                case 1:
                    v = -std::abs(any(rng));
                    break;  // all below 0
                case 2:
                    v = small(rng);
                    break;  // crossing 0 often
                case 3:
                    v = d % 3 == 0 ? 0.0f : small(rng);
                    break;  // ends exactly at 0
                case 4:
                    v = base;
                    break;  // equal neighbours
                case 5:
                    v = std::nextafter(base, d % 2 ? 2.0f : -2.0f);
                    break;  // one ulp apart
                case 6:
                    v = d % 2 ? float(kPi / 2) : float(-kPi / 2);
                    break;  // extremes
                default:
                    v = any(rng);
                    break;
            }
            set.plane(d)[t] = v;
        }
        if (t % 37 == 11) set.plane(int(t % std::size_t(directions)))[t] = std::nanf("");  // void receiver
    }
    return set;
}

// The per-texel double reference of log_sh: ts_hf_add_slice's sum with libm sines and cosines.
std::vector<double> reference_log_sh(const HorizonSet& set, std::size_t t, double log_eps) {
    namespace shared = ts::sh::shared;
    const int D = set.directions;
    const double delta = 2 * kPi / D;
    std::vector<double> f(16, 0.0);
    for (int d = 0; d < D; ++d) {
        double e[10];
        shared::ts_slice_sh_integrals(set.plane(d)[t], log_eps, e);
        for (int i = 0; i < 16; ++i) {
            const int l = ts::sh::band_of(i), m = ts::sh::order_of(i);
            f[std::size_t(i)] +=
                shared::ts_slice_azimuth_weight(m, azimuth_rad(d, D), delta) * e[l * (l + 1) / 2 + std::abs(m)];
        }
    }
    return f;
}

bool is_void(const HorizonSet& set, std::size_t t) {
    for (int d = 0; d < set.directions; ++d)
        if (std::isnan(set.plane(d)[t])) return true;
    return false;
}

}  // namespace

TEST(VisibilityProducts, MatchPerTexelLibmFormulas) {
    // Everything in double and rounded to float once: within float rounding of the per-texel
    // libm formulas in double (half an ulp is 6e-8 relative; the polynomials add < 1e-13).
    // log-SH: 1e-7 * max(1, |ref|); svf and sky_visible (in [0, 1]): 1e-7 absolute (measured 5.9e-8
    // and 3.0e-8; a wrong crossing split or slice weight is off by 1e-3 or more).
    for (int D : {4, 7, 32}) {
        const HorizonSet set = awkward_set(50, 45, D);  // 2250 texels: several blocks, 2 work items, a tail
        ProductRequest r;
        r.log_eps = -2.5f;
        r.threads = 2;
        const VisibilityProducts p = visibility_products(set, r);
        ASSERT_EQ(p.log_sh.size(), set.texels() * 16);
        double sh_err = 0, svf_err = 0, sky_err = 0;
        int voids = 0;
        for (std::size_t t = 0; t < set.texels(); ++t) {
            if (is_void(set, t)) {
                ++voids;
                EXPECT_TRUE(std::isnan(p.svf[t]) && std::isnan(p.sky_visible[t])) << t;
                for (int i = 0; i < 16; ++i) EXPECT_TRUE(std::isnan(p.log_sh[std::size_t(i) * set.texels() + t]));
                continue;
            }
            const auto ref = reference_log_sh(set, t, r.log_eps);
            for (int i = 0; i < 16; ++i) {
                const double got = p.log_sh[std::size_t(i) * set.texels() + t];
                sh_err = std::max(sh_err,
                                  std::abs(got - ref[std::size_t(i)]) / std::max(1.0, std::abs(ref[std::size_t(i)])));
            }
            svf_err = std::max(svf_err, std::abs(p.svf[t] - sky_view_factor(set.angle.data() + t, D, set.texels())));
            sky_err = std::max(
                sky_err, std::abs(p.sky_visible[t] - sky_visible_fraction(set.angle.data() + t, D, set.texels())));
        }
        EXPECT_GT(voids, 50);
        EXPECT_LT(sh_err, 1e-7) << "D = " << D;
        EXPECT_LT(svf_err, 1e-7) << "D = " << D;
        EXPECT_LT(sky_err, 1e-7) << "D = " << D;
    }
}

TEST(VisibilityProducts, SubsetsEqualTheFullPassAndFewDirections) {
    const HorizonSet set = awkward_set(70, 3, 16);
    const VisibilityProducts all = visibility_products(set);
    ProductRequest only_svf;
    only_svf.log_sh = only_svf.sky_visible = false;
    only_svf.threads = 1;
    const VisibilityProducts svf = visibility_products(set, only_svf);
    EXPECT_TRUE(svf.log_sh.empty());
    EXPECT_TRUE(svf.sky_visible.empty());
    ASSERT_EQ(svf.svf.size(), set.texels());
    for (std::size_t t = 0; t < set.texels(); ++t)
        EXPECT_TRUE(svf.svf[t] == all.svf[t] || (std::isnan(svf.svf[t]) && std::isnan(all.svf[t]))) << t;
    // The raster functions go through the same pass.
    const auto log_sh = log_sh_raster(set);
    for (std::size_t k = 0; k < log_sh.size(); ++k)
        EXPECT_TRUE(log_sh[k] == all.log_sh[k] || (std::isnan(log_sh[k]) && std::isnan(all.log_sh[k]))) << k;

    // Sky products work from one azimuth on (D = 1: a constant horizon all round); log-SH needs 4.
    for (int D : {1, 2, 3}) {
        const HorizonSet few = awkward_set(9, 2, D);
        ProductRequest sky;
        sky.log_sh = false;
        const VisibilityProducts p = visibility_products(few, sky);
        for (std::size_t t = 0; t < few.texels(); ++t) {
            if (is_void(few, t)) continue;
            EXPECT_NEAR(p.svf[t], sky_view_factor(few.angle.data() + t, D, few.texels()), 1e-7) << D;
            EXPECT_NEAR(p.sky_visible[t], sky_visible_fraction(few.angle.data() + t, D, few.texels()), 1e-7) << D;
        }
        EXPECT_THROW(visibility_products(few), ts::InputError);
    }
}
