// The bounced light's transfer (core/render/bounce_transfer.hpp): its view weights against a
// brute-force integral, its gather's scaling (terrain that all reflects alike gives exactly the
// blocked part of the view times that), the bounce counts, and the band correction calibrated
// on a level texel.
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "core/render/bounce_transfer.hpp"
#include "core/render/shading_state.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "tests/render/grey_materials.hpp"

namespace ts::render {
namespace {

constexpr double kPi = std::numbers::pi;

// The cosine-weighted solid angle below the horizons, in front of the receiver's plane, by brute force.
double brute_force_blocked(const std::vector<float>& h, const glm::dvec3& n) {
    double blocked = 0;
    const int d_count = int(h.size()), steps = 4000;
    const double de = kPi / steps;
    for (int d = 0; d < d_count; ++d) {
        const double phi = 2 * kPi * d / d_count;
        for (int k = 0; k < steps; ++k) {
            const double e = -kPi / 2 + (k + 0.5) * de;
            const glm::dvec3 dir(std::cos(e) * std::cos(phi), std::cos(e) * std::sin(phi), std::sin(e));
            const double c = n.x * dir.x + n.y * dir.y + n.z * dir.z;
            if (c > 0 && e < h[std::size_t(d)]) blocked += c * std::cos(e) * de * 2 * kPi / d_count;
        }
    }
    return blocked;
}

TEST(BounceTransfer, TheBlockedViewMatchesItsIntegral) {
    const int d_count = 32;
    visibility::HorizonSet set;
    set.width = set.height = 1;
    set.directions = d_count;
    set.angle.resize(std::size_t(d_count));
    // A level receiver under a uniform horizon: pi sin^2 h.
    for (int d = 0; d < d_count; ++d) set.angle[std::size_t(d)] = 0.3f;
    EXPECT_NEAR(blocked_view(set, 0, {0, 0, 1}), kPi * std::sin(0.3f) * std::sin(0.3f), 1e-6);
    // A slope tilted 30 degrees to the east under varying horizons, some below the horizontal.
    std::vector<float> h(static_cast<std::size_t>(d_count), 0.0f);
    for (int d = 0; d < d_count; ++d)
        h[std::size_t(d)] = set.angle[std::size_t(d)] = float(0.25 * std::sin(2 * kPi * d / d_count) - 0.1);
    const glm::dvec3 n(std::sin(kPi / 6), 0, std::cos(kPi / 6));
    EXPECT_NEAR(blocked_view(set, 0, n), brute_force_blocked(h, n), 2e-3 * kPi);
    EXPECT_GT(blocked_view(set, 0, n), 0.05);
}

// A V-shaped valley, 48 x 48 texels of 30 m, slopes of 0.6.
struct Valley {
    std::vector<float> z;
    terrain::HeightGrid grid;
    visibility::HorizonSet horizons;
    NormalField normals;
    // `holes`: a few void texels (NaN heights) on the slopes and the floor. `width`: the rows'
    // (48 rows, the floor along the middle column).
    explicit Valley(bool holes = false, int width = 48) : z(std::size_t(width) * 48) {
        for (int r = 0; r < 48; ++r)
            for (int c = 0; c < width; ++c)
                z[std::size_t(r * width + c)] = float(0.6 * 30 * std::abs(c - (width - 1) / 2.0));
        if (holes)
            for (auto [r, c] : {std::pair{10, 5}, {20, 23}, {20, 24}, {30, 40}, {47, width - 1}})
                z[std::size_t(r * width + c)] = std::numeric_limits<float>::quiet_NaN();
        grid = terrain::HeightGrid::uniform(width, 48, z, 30, 30);
        visibility::HorizonOptions o;
        o.directions = 32;
        o.curvature = false;
        horizons = visibility::compute_horizons(grid, o);
        normals = terrain_normals(grid);
    }
    // T_d the same everywhere: flat ground's.
    std::vector<float> constant_transfer() const {
        const std::array<float, 16> flat = flat_transfer();
        std::vector<float> t(16 * z.size());
        for (int i = 0; i < 16; ++i)
            for (std::size_t k = 0; k < z.size(); ++k) t[std::size_t(i) * z.size() + k] = flat[std::size_t(i)];
        return t;
    }
    BounceInputs inputs(const std::vector<float>& transfer, const std::vector<float>& albedo) const {
        BounceInputs in;
        in.grid = &grid;
        in.horizons = &horizons;
        in.normals = &normals;
        in.albedo = albedo;
        in.transfer = transfer.data();
        in.coefficients = 9;
        in.threads = 2;
        return in;
    }
};

TEST(BounceTransfer, TerrainThatReflectsAlikeGivesTheBlockedViewTimesItsLight) {
    const Valley v;
    const std::vector<float> t = v.constant_transfer();
    const std::vector<float> albedo(v.z.size(), 0.5f);
    const std::array<float, 16> flat = flat_transfer();
    const std::size_t n = v.z.size();
    const BounceSettings s;  // its sectors: every (32 / sectors)-th of the 32 horizons
    const int sectors = s.gather.directions;
    ASSERT_EQ(32 % sectors, 0);
    const std::vector<float> b = bounce_transfer(v.inputs(t, albedo), s);
    ASSERT_EQ(b.size(), 9 * n);
    std::vector<double> cos_phi, sin_phi;
    for (int d = 0; d < sectors; ++d)
        cos_phi.push_back(std::cos(2 * kPi * d / sectors)), sin_phi.push_back(std::sin(2 * kPi * d / sectors));
    for (int r = 8; r < 40; r += 7)
        for (int c = 4; c < 44; c += 3) {
            const std::size_t k = std::size_t(r * 48 + c);
            // The blocked view at the gather's sectors.
            const double sr = visibility::blocked_view(v.horizons.angle.data() + k, std::size_t(32 / sectors) * n,
                                                       sectors, cos_phi.data(),
                                                       sin_phi.data(), v.normals.x[k], v.normals.y[k], v.normals.z[k]);
            // Within 1%: the march's bilinear samples may rise a little above the exact horizon.
            for (int i = 0; i < 9; ++i) {
                const double want = sr / kPi * 0.5 * flat[std::size_t(i)];
                EXPECT_NEAR(b[std::size_t(i) * n + k], want, 0.01 * std::abs(want) + 1e-7)
                    << "texel " << c << "," << r << " coefficient " << i;
            }
        }
    // The valley floor sees the slopes (31 degrees up across the valley, open along it): a sixth of its view.
    const std::size_t floor = 24 * 48 + 23;
    EXPECT_GT(blocked_view(v.horizons, floor, {v.normals.x[floor], v.normals.y[floor], v.normals.z[floor]}),
              0.15 * kPi);
    BounceSettings none;
    none.bounces = 0;
    EXPECT_TRUE(bounce_transfer(v.inputs(t, albedo), none).empty());
}

TEST(BounceTransfer, ASecondBounceAddsAndBlackTerrainBouncesNothing) {
    const Valley v;
    const std::vector<float> t = v.constant_transfer();
    const std::size_t n = v.z.size(), floor = 24 * 48 + 23;
    BounceSettings one, two;
    two.bounces = 2;
    const std::vector<float> grey(n, 0.5f), black(n, 0.0f);
    const std::vector<float> b1 = bounce_transfer(v.inputs(t, grey), one);
    const std::vector<float> b2 = bounce_transfer(v.inputs(t, grey), two);
    // The second bounce is the first's light reflected once more: about albedo x blocked / pi of it.
    EXPECT_GT(b2[floor], b1[floor] * 1.02f);
    EXPECT_LT(b2[floor], b1[floor] * 1.5f);
    for (float x : bounce_transfer(v.inputs(t, black), two)) EXPECT_EQ(x, 0.0f);
}

// The weights recorded for the sun part are T_b's own: summed over any per-texel values they give
// T_b again (here its coefficients, with a transfer that varies by texel), and the second bounce
// applies them once more. Voids keep their neighbours' entries apart and get nothing.
void expect_weights_reproduce_the_bounce_transfer(bool holes, int width = 48) {
    SCOPED_TRACE(holes ? "with voids" : "without voids");
    SCOPED_TRACE("width " + std::to_string(width));
    const Valley v(holes, width);
    const std::size_t n = v.z.size();
    std::vector<float> t = v.constant_transfer();
    for (std::size_t k = 0; k < n; ++k) t[k] *= float(1.0 + 0.3 * std::sin(0.37 * double(k)));  // band 0 varies
    std::vector<float> albedo(n);
    for (std::size_t k = 0; k < n; ++k) albedo[k] = float(0.3 + 0.2 * std::cos(0.11 * double(k)));
    const std::array<float, 16> flat = flat_transfer();
    for (int bounces : {1, 2}) {
        BounceSettings s;
        s.bounces = bounces;
        BounceSunGather g;
        const std::vector<float> b = bounce_transfer(v.inputs(t, albedo), s, &g);
        ASSERT_EQ(g.texels(), n);
        EXPECT_EQ(g.bounces(), bounces);
        EXPECT_GT(g.entries(), n);  // the valley's texels see its other side
        // Per frame the values are the transfer's band 0, and the sun's z is flat_0: apply() adds
        // far_t max(0, s_z) = far_t flat_0, T_b's far term in band 0.
        std::vector<float> values(t.begin(), t.begin() + std::ptrdiff_t(n)), out(n), portable(n), first(n);
        BounceSunGather::Scratch scratch;
        g.apply(values.data(), flat[0], out.data(), scratch, 2);
        // The vector units' sums and the portable loop's agree (their order of adds differs).
        g.apply(values.data(), flat[0], portable.data(), scratch, 1, false);
        for (std::size_t k = 0; k < n; ++k) ASSERT_NEAR(out[k], portable[k], 1e-6f * std::abs(out[k])) << k;
        if (bounces == 2) {
            BounceSettings one = s;
            one.bounces = 1;
            BounceSunGather g1;
            bounce_transfer(v.inputs(t, albedo), one, &g1);
            g1.apply(values.data(), flat[0], first.data(), scratch, 2);
        }
        for (std::size_t k = 0; k < n; ++k) {
            if (std::isnan(b[k])) {
                ASSERT_EQ(out[k], 0.0f) << "void texel " << k;
            } else if (bounces == 1) {
                // The weights in 8 bits against each receiver's largest, the rounding carried from
                // one to the next: ~1e-3 of the sum where the values vary (here by 30%).
                ASSERT_NEAR(out[k], b[k], 3e-3 * std::abs(b[k]) + 1e-9) << "texel " << k;
            } else {  // b1 + sum_j w_tj b1_j: T_b's second pass over its first
                ASSERT_NEAR(out[k], b[k], 4e-3 * std::abs(b[k]) + 1e-9) << "texel " << k;
                ASSERT_GE(out[k], first[k]);
            }
        }
    }
}

TEST(BounceSunGather, ItsWeightsAreTheBounceTransfers) {
    expect_weights_reproduce_the_bounce_transfer(false);
    expect_weights_reproduce_the_bounce_transfer(true);
    // Rows that end in a part of a chunk of 8 receivers.
    expect_weights_reproduce_the_bounce_transfer(true, 45);
    // With no bounce, no weights.
    const Valley v;
    const std::vector<float> t = v.constant_transfer(), albedo(v.z.size(), 0.5f);
    BounceSettings none;
    none.bounces = 0;
    BounceSunGather g;
    EXPECT_TRUE(bounce_transfer(v.inputs(t, albedo), none, &g).empty());
    EXPECT_TRUE(g.empty());
}

// A chunk added whole (the gather's chunk march) keeps the weights that adding its receivers
// one by one keeps: the same offsets, and sums within the 8-bit codes' rounding (the two orders
// of the offsets carry the rounding differently). Rows of 20: the last chunk has 4 receivers.
TEST(BounceSunGather, AChunkAddedWholeIsItsReceiversAddedOneByOne) {
    constexpr int kW = 20, kH = 6, kLanes = BounceSunGather::kLanes;
    BounceSunGather whole(1, kW, kH), one_by_one(1, kW, kH);
    {
        BounceSunGather::Writer chunks(whole), receivers(one_by_one);
        for (int row = 0; row < kH; ++row)
            for (int col0 = 0; col0 < kW; col0 += kLanes) {
                std::vector<BounceSunGather::Writer::ChunkEntry> entries;
                for (int e = 0; e < 7; ++e) {
                    BounceSunGather::Writer::ChunkEntry& x = entries.emplace_back();
                    x.dc = (e * 5 + row) % 7 - 3, x.dr = (e * 3 + col0) % 5 - 2;
                    for (int l = 0; l < kLanes; ++l)
                        x.weight[l] = (e + l + row) % 3 == 0 ? 0.0f : float(0.01 * (1 + (e * 7 + l * 3 + row) % 11));
                }
                // Lane 2 of the second chunk is left out (a void); lanes beyond the row do not exist.
                unsigned lanes = 0;
                float far[kLanes];
                for (int l = 0; l < kLanes && col0 + l < kW; ++l) {
                    far[l] = 0.001f * float(l + 1);
                    if (!(col0 == kLanes && l == 2)) lanes |= 1u << l;
                }
                for (int l = 0; l < kLanes; ++l) {
                    if (!(lanes >> l & 1u)) continue;
                    const int col = col0 + l;
                    std::vector<std::uint32_t> texels;
                    std::vector<float> weights;
                    for (const auto& x : entries) {
                        const int c = col + x.dc, r = row + x.dr;
                        if (x.weight[l] == 0.0f || c < 0 || r < 0 || c >= kW || r >= kH) continue;
                        texels.push_back(std::uint32_t(r * kW + c));
                        weights.push_back(x.weight[l]);
                    }
                    receivers.add(col, row, texels, weights, far[l]);
                }
                // The chunk's entries, without those of lanes beyond the grid (as the march has them).
                for (auto& x : entries)
                    for (int l = 0; l < kLanes; ++l) {
                        const int c = col0 + l + x.dc, r = row + x.dr;
                        if (!(lanes >> l & 1u) || c < 0 || r < 0 || c >= kW || r >= kH) x.weight[l] = 0.0f;
                    }
                chunks.add_chunk(col0, row, lanes, entries.data(), entries.size(), far);
            }
        chunks.finish();
        receivers.finish();
    }
    EXPECT_EQ(whole.entries(), one_by_one.entries());
    EXPECT_GT(whole.entries(), std::size_t(kW * kH * 3));
    const std::size_t n = std::size_t(kW) * kH;
    std::vector<float> values(n), a(n), b(n);
    for (std::size_t k = 0; k < n; ++k) values[k] = float(0.5 + 0.4 * std::sin(0.7 * double(k)));
    BounceSunGather::Scratch scratch;
    whole.apply(values.data(), 0.5f, a.data(), scratch, 1);
    one_by_one.apply(values.data(), 0.5f, b.data(), scratch, 1);
    for (std::size_t k = 0; k < n; ++k) {
        EXPECT_NEAR(a[k], b[k], 3e-3 * std::abs(b[k])) << k;
        EXPECT_EQ(whole.far()[k], one_by_one.far()[k]) << k;
    }
    EXPECT_EQ(a[std::size_t(kLanes + 2)], 0.0f);  // the receiver left out
}

// A texel whose whole view of the terrain is in shadow gets only the far ground's sun: what the
// SH sun part (the neighbours' smooth, SH-lit sun) cannot tell.
TEST(BounceSunGather, TerrainInShadowBouncesNoSun) {
    const Valley v;
    const std::size_t n = v.z.size(), floor = 24 * 48 + 23;
    const std::vector<float> t = v.constant_transfer(), albedo(n, 0.5f);
    BounceSunGather g;
    bounce_transfer(v.inputs(t, albedo), BounceSettings{}, &g);
    std::vector<float> lit(n, 0.8f), dark(n, 0.0f), out_lit(n), out_dark(n);
    BounceSunGather::Scratch scratch;
    g.apply(lit.data(), 0.5f, out_lit.data(), scratch, 1);
    g.apply(dark.data(), 0.5f, out_dark.data(), scratch, 1);
    EXPECT_NEAR(out_dark[floor], g.far()[floor] * 0.5f, 1e-7);
    EXPECT_GT(out_lit[floor], out_dark[floor] + 0.01f);
}

TEST(BounceTransfer, RefusesBadSettings) {
    BounceSettings s;
    s.bounces = 3;
    EXPECT_THROW(check_bounce_settings(s), InputError);
    s.bounces = 1;
    s.gather.radius_texels = 0;
    EXPECT_THROW(check_bounce_settings(s), InputError);
    // The sun's gather holds its entries within 126 texels; through SH the radius may be larger.
    s.gather.radius_texels = 200;
    EXPECT_THROW(check_bounce_settings(s), InputError);
    s.sun = BounceSettings::SunPart::sh;
    EXPECT_NO_THROW(check_bounce_settings(s));
}

// An open level texel's diffuse transfer is the projected clamped cosine exactly: the band
// correction is calibrated on a level texel's own horizons (its log floor below them), not on
// a receiver with nothing below it at all.
TEST(BandCorrection, ALevelTexelsTransferIsTheProjectedCosine) {
    std::vector<float> z(24 * 24, 800.0f);
    const terrain::HeightGrid grid = terrain::HeightGrid::uniform(24, 24, z, 30, 30);
    RendererOptions o;
    o.directions = 16;
    o.curvature = false;
    o.threads = 2;
    o.keep_diffuse_transfer = true;
    auto state = compute_shading_state(grid, testing::grey_materials(grid, 0.3f), terrain_normals(grid), o);
    const std::array<float, 16> flat = flat_transfer();
    const std::vector<float>& t = state->kept_diffuse_transfer();
    const std::size_t k = 12 * 24 + 12, n = z.size();
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(t[std::size_t(i) * n + k], flat[std::size_t(i)], 2e-4) << i;
    EXPECT_TRUE(state->bounce_transfer().empty());  // nothing above a level texel's plane
}

}  // namespace
}  // namespace ts::render
