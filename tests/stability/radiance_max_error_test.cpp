// render/relight/tiles/fly --max-error (core/quality/radiance_quality.hpp) meets its bound
// against the ray-traced reference on the shared DEMs: for each DEM, a 48 x 48 crop a quarter of
// the way in (away from the windows the table was fitted on), suns at elevations between the
// fitted ones, and bounds from loose to tight, the chosen setting's relative radiance RMSE
// (luminance, RMSE / mean of the reference, as bench render measures it) is at most E wherever
// a setting is predicted to meet it. The same for the tiles' relief against its reference.
// Also: flat ground gets the cheapest setting, an impossible bound says so, E <= 0 is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "core/dem/crop.hpp"
#include "core/dem/read_dem.hpp"
#include "core/light/sky.hpp"
#include "core/quality/radiance_quality.hpp"
#include "core/quality/visibility_quality.hpp"
#include "core/render/frame_renderer.hpp"
#include "core/render/reference_shading.hpp"
#include "core/render/tone_map.hpp"
#include "core/terrain/terrain_normals.hpp"
#include "app/bench/study/reference_relief.hpp"
#include "core/tiles/shade_source.hpp"
#include "core/util/error.hpp"
#include "core/visibility/visibility_grid.hpp"

namespace ts {
namespace {

constexpr int kCrop = 48;
constexpr int kStride = 11;  // every 11th texel goes to the reference: 210 of the crop's 2304

// RMSE / mean of the reference (bench::relative_errors' rmse).
double relative_rmse(const std::vector<double>& got, const std::vector<double>& want) {
    double se = 0, sum = 0;
    for (std::size_t i = 0; i < got.size(); ++i) se += (got[i] - want[i]) * (got[i] - want[i]), sum += want[i];
    return std::sqrt(se / double(got.size())) / (sum / double(got.size()));
}

dem::Dem shared_crop(const std::string& name) {
    const dem::Dem full = dem::read_dem(std::string(TS_SHARED_DATA) + "/dem/" + name);
    return dem::texel_window(full, full.width / 4, full.height / 4, kCrop, kCrop);
}

struct Sun {
    double azimuth, elevation;
};
const Sun kSuns[] = {{230.0, 4.0}, {110.0, 28.0}};
const double kBounds[] = {0.10, 0.065, 0.0635, 0.045, 0.037, 0.025};

class RadianceMaxError : public ::testing::TestWithParam<std::string> {};

TEST_P(RadianceMaxError, TheChosenSettingMeetsTheBoundAgainstTheReference) {
    const dem::Dem d = shared_crop(GetParam());
    const visibility::VisibilityGrid vgrid(d);
    const terrain::HeightGrid& grid = vgrid.view();
    const render::NormalField normals = render::terrain_normals(grid, 0);
    const render::MaterialRaster materials = render::rule_materials(grid, normals);
    const render::ViewDirections view;
    std::vector<std::size_t> texels;
    for (std::size_t i = 0; i < grid.z.size(); i += kStride) texels.push_back(i);
    const render::ReferenceShader reference(grid, materials, normals, view, texels);
    quality::RadianceScene scene;
    scene.roughness = quality::mean_tan_slope(grid);
    int met = 0;
    for (const Sun& s : kSuns) {
        const render::SunState sun{s.azimuth, s.elevation};
        const auto sky = light::make_sky(light::SkyOptions{}, render::sun_direction(sun));
        const std::vector<render::ReferenceSample> ref = reference.render(*sky, sun);
        scene.sun_elevations_deg = {s.elevation};
        for (double e : kBounds) {
            const quality::RadianceChoice c = quality::choose_radiance(e, scene);
            if (!c.met) {
                EXPECT_NE(c.reason.find("no setting"), std::string::npos) << c.reason;
                continue;
            }
            render::RendererOptions ro;
            ro.directions = c.directions;
            ro.sun_method = c.exact_sun ? visibility::SunMethod::exact : visibility::SunMethod::sweep;
            const auto state = render::compute_shading_state(grid, materials, normals, ro);
            const render::ViewShading vs = render::compute_view_shading(*state, view);
            render::FrameRenderer renderer(*state, vs);
            std::vector<glm::vec3> frame;
            renderer.render(*sky, sun, frame);
            std::vector<double> got, want;
            for (std::size_t k = 0; k < texels.size(); ++k) {
                const double a = render::luminance(frame[texels[k]]), b = render::luminance(ref[k].radiance);
                if (std::isfinite(a) && std::isfinite(b)) got.push_back(a), want.push_back(b);
            }
            ASSERT_GT(got.size(), texels.size() / 2);
            const double measured = relative_rmse(got, want);
            ++met;
            std::printf("%s: sun %.0f deg, E %g -> D %d%s: predicted %.3f, measured %.3f\n", GetParam().c_str(),
                        s.elevation, e, c.directions, c.exact_sun ? " exact sun" : "", c.predicted_error, measured);
            EXPECT_LE(measured, e) << GetParam() << ": " << c.reason << "; measured " << measured;
        }
    }
    EXPECT_GE(met, 2) << "the loose bounds are met by some setting";
}

// tiles --style relief at a native zoom (level 0, no exaggeration): the relief values against
// reference_relief on the crop's central 12 x 12 texels.
TEST_P(RadianceMaxError, TheTilesReliefMeetsTheBoundAgainstItsReference) {
    const dem::Dem d = shared_crop(GetParam());
    tiles::TileShading shading;
    shading.style = tiles::find_tile_style("relief");
    const tiles::LevelWindow window{18, 18, 12, 12};
    const std::vector<float> ref = tiles::reference_relief(d, shading, 0, 1.0, window);
    quality::RadianceScene scene;
    scene.roughness = quality::mean_tan_slope(visibility::VisibilityGrid(d).view());
    scene.sun_elevations_deg = {shading.sun_elevation_deg};
    scene.exact_sun_available = false;
    int met = 0;
    for (double e : kBounds) {
        const quality::RadianceChoice c = quality::choose_radiance(e, scene);
        if (!c.met) continue;
        shading.directions = c.directions;
        const tiles::ShadeSource src = tiles::make_shade_source(d, shading, 0, 1.0);
        std::vector<double> got, want;
        for (int r = 0; r < window.height; ++r)
            for (int col = 0; col < window.width; ++col) {
                const double a = src.values[std::size_t(window.row0 + r) * std::size_t(src.width) + std::size_t(window.col0 + col)];
                const double b = ref[std::size_t(r) * std::size_t(window.width) + std::size_t(col)];
                if (std::isfinite(a) && std::isfinite(b)) got.push_back(a), want.push_back(b);
            }
        ASSERT_FALSE(got.empty());
        const double measured = relative_rmse(got, want);
        ++met;
        std::printf("%s relief: E %g -> D %d: predicted %.3f, measured %.3f\n", GetParam().c_str(), e, c.directions,
                    c.predicted_error, measured);
        EXPECT_LE(measured, e) << GetParam() << ": " << c.reason << "; measured " << measured;
    }
    EXPECT_GE(met, 1);
}

INSTANTIATE_TEST_SUITE_P(SharedDems, RadianceMaxError,
                         ::testing::Values("copernicus_N45E005_grenoble_500px.tif", "srtm3_N39E040_1000px.tif",
                                           "N00E010.hgt", "N00E011.hgt.zip"),
                         [](const ::testing::TestParamInfo<std::string>& p) { return std::to_string(p.index); });

TEST(RadianceMaxErrorChoice, FlatGroundGetsTheCheapestSettingAndAnImpossibleBoundSaysSo) {
    const auto& settings = quality::radiance_settings();
    ASSERT_GE(settings.size(), 2u);
    quality::RadianceScene flat;
    flat.roughness = 0;
    flat.sun_elevations_deg = {45.0};
    // A bound the cheapest setting meets on flat ground under a high sun.
    const double cheap_error = quality::predicted_radiance_error(settings.front(), 0.0, 45.0);
    const auto cheap = quality::choose_radiance(cheap_error * 1.01, flat);
    EXPECT_TRUE(cheap.met);
    EXPECT_EQ(cheap.directions, settings.front().directions);
    EXPECT_NE(cheap.reason.find("the cheapest setting under the bound"), std::string::npos) << cheap.reason;
    quality::RadianceScene steep;
    steep.roughness = 0.6;
    steep.sun_elevations_deg = {2.0};
    const auto none = quality::choose_radiance(1e-6, steep);
    EXPECT_FALSE(none.met);
    EXPECT_EQ(none.directions, settings.back().directions);
    EXPECT_NE(none.reason.find("no setting"), std::string::npos);
    steep.exact_sun_available = false;
    EXPECT_FALSE(quality::choose_radiance(1e-6, steep).exact_sun);
    EXPECT_THROW(quality::choose_radiance(0.0, flat), InputError);
    EXPECT_THROW(quality::choose_radiance(-0.1, flat), InputError);
}

TEST(RadianceMaxErrorChoice, ASequenceIsPredictedAtItsWorstSun) {
    quality::RadianceScene one, many;
    one.roughness = many.roughness = 0.2;
    one.sun_elevations_deg = {quality::lowest_fitted_elevation()};
    many.sun_elevations_deg = {60.0, quality::lowest_fitted_elevation(), 30.0};
    const auto a = quality::choose_radiance(0.05, one), b = quality::choose_radiance(0.05, many);
    EXPECT_EQ(a.directions, b.directions);
    EXPECT_DOUBLE_EQ(a.predicted_error, b.predicted_error);
    EXPECT_DOUBLE_EQ(b.worst_sun_elevation_deg, quality::lowest_fitted_elevation());
}

}  // namespace
}  // namespace ts
