#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "core/geo/crs.hpp"
#include "core/render/perspective_view.hpp"
#include "core/util/error.hpp"

namespace ts::render {
namespace {

// A 1-metre UTM grid: easy to place a camera on by lon/lat through the georef.
struct Scene {
    int w = 64, h = 64;
    std::vector<float> z;
    terrain::HeightGrid grid;
    geo::Georef georef;
    Scene() : z(std::size_t(64 * 64), 100.0f) {
        grid = terrain::HeightGrid::uniform(w, h, z, 10.0, 10.0);
        geo::GeoTransform t{500000.0, 10.0, 0.0, 5000000.0, 0.0, -10.0};
        georef = geo::Georef(w, h, t, geo::Crs::from_epsg(32631), true);
    }
    Camera above_centre(double height, double pitch) const {
        const glm::dvec2 ll = georef.pixel_to_lonlat(32.0, 32.0);
        Camera c;
        c.lon_deg = ll.x, c.lat_deg = ll.y, c.height_m = height, c.heading_deg = 0, c.pitch_deg = pitch, c.fov_deg = 40;
        return c;
    }
};

TEST(PerspectiveView, LookingDownHitsEverywhereLookingUpNowhere) {
    Scene s;
    PerspectiveOptions o;
    o.width = 32, o.height = 18;
    o.curvature = false;
    const PerspectiveView down(s.grid, s.georef, s.above_centre(400, -90), o);
    EXPECT_EQ(down.hit_count(), 32u * 18u);
    const PerspectiveView up(s.grid, s.georef, s.above_centre(400, 60), o);
    EXPECT_EQ(up.hit_count(), 0u);
}

TEST(PerspectiveView, HitsLandWhereTheFlatPlaneIs) {
    // Camera 100 m above a plane (at 200 m), looking down 45 degrees north: the centre ray hits
    // 100 m north of the camera = 10 texels up (rows decrease northwards).
    Scene s;
    PerspectiveOptions o;
    o.width = 3, o.height = 3;
    o.curvature = false;
    o.haze_distance_m = 0;
    const PerspectiveView v(s.grid, s.georef, s.above_centre(200, -45), o);
    ASSERT_EQ(v.hit_count(), 9u);
    // Compose a radiance that encodes the row: the hit row comes back through the bilinear lookup.
    std::vector<glm::vec3> rad(std::size_t(s.w * s.h));
    for (int r = 0; r < s.h; ++r)
        for (int c = 0; c < s.w; ++c) rad[std::size_t(r * s.w + c)] = glm::vec3(float(r), float(c), 0);
    light::SkyTable sky(light::SkyGrid::whole_sphere(8, 4));
    std::vector<glm::vec3> img;
    v.compose(rad.data(), nullptr, sky, {0, 0, 1}, {0, 0, 0}, 1.0, img);
    // The camera sits at texel-centre (31.5, 31.5); the hit is 10 texels north. Tolerance:
    // the bisection's resolution (1/16 of a sub-step) and float positions.
    EXPECT_NEAR(img[4].x, 21.5f, 0.05f);
    EXPECT_NEAR(img[4].y, 31.5f, 0.05f);
}

TEST(PerspectiveView, ARidgeHidesWhatIsBehindIt) {
    // A 300 m ridge 10 texels north of the camera hides the plane behind it from a camera
    // looking north just below the horizontal.
    Scene s;
    for (int c = 0; c < s.w; ++c) s.z[std::size_t(20 * s.w + c)] = 300.0f;
    s.grid = terrain::HeightGrid::uniform(s.w, s.h, s.z, 10.0, 10.0);
    PerspectiveOptions o;
    o.width = 1, o.height = 1;
    o.curvature = false;
    o.haze_distance_m = 0;
    const PerspectiveView v(s.grid, s.georef, s.above_centre(150, -2), o);
    ASSERT_EQ(v.hit_count(), 1u);
    std::vector<glm::vec3> rad(std::size_t(s.w * s.h));
    for (int r = 0; r < s.h; ++r)
        for (int c = 0; c < s.w; ++c) rad[std::size_t(r * s.w + c)] = glm::vec3(float(r), 0, 0);
    light::SkyTable sky(light::SkyGrid::whole_sphere(8, 4));
    std::vector<glm::vec3> img;
    v.compose(rad.data(), nullptr, sky, {0, 0, 1}, {0, 0, 0}, 1.0, img);
    EXPECT_GT(img[0].x, 19.0f);  // on the ridge's south face (rows 20..21), not beyond it
    EXPECT_LT(img[0].x, 21.5f);
}

// A frame's per-texel radiance as FrameRenderer makes it: a sky part plus the sun's diffuse term
// albedo v E/pi max(0, n.s) with the texel's normal (E/pi = 1 here).
struct SunFrame {
    std::vector<glm::vec3> radiance;
    std::vector<float> albedo, visibility, nx, ny, nz;
    TexelSunTerm term;
    SunFrame(const terrain::HeightGrid& g, const glm::vec3& sun, const std::vector<float>& texel_visibility)
        : visibility(texel_visibility) {
        const std::size_t n = std::size_t(g.width) * g.height;
        nx.assign(n, 0.0f), ny.assign(n, 0.0f), nz.assign(n, 1.0f), albedo.assign(n, 0.5f);
        for (std::size_t t = 0; t < n; ++t) radiance.push_back(glm::vec3(0.1f + albedo[t] * visibility[t] * sun.z));
        term.albedo_r = term.albedo_g = term.albedo_b = albedo.data();
        term.visibility = visibility.data();
        term.nx = nx.data(), term.ny = ny.data(), term.nz = nz.data();
        term.direction = sun;
        term.irradiance_over_pi = glm::vec3(1.0f);
    }
};

TEST(PerspectiveView, AFlatPlaneLooksTheSameShadedPerPixel) {
    Scene s;
    PerspectiveOptions o;
    o.width = 16, o.height = 9;
    o.curvature = false;
    o.haze_distance_m = 0;
    const PerspectiveView v(s.grid, s.georef, s.above_centre(300, -60), o);
    const glm::vec3 sun = glm::normalize(glm::vec3(0.3f, -0.5f, 0.6f));
    const SunFrame frame(s.grid, sun, std::vector<float>(std::size_t(s.w * s.h), 1.0f));
    light::SkyTable sky(light::SkyGrid::whole_sphere(8, 4));
    std::vector<glm::vec3> per_texel, per_pixel;
    v.compose(frame.radiance.data(), nullptr, sky, sun, {0, 0, 0}, 0.99999, per_texel);
    v.compose(frame.radiance.data(), &frame.term, sky, sun, {0, 0, 0}, 0.99999, per_pixel);
    ASSERT_EQ(v.hit_count(), per_pixel.size());
    for (std::size_t k = 0; k < per_pixel.size(); ++k) {
        EXPECT_NEAR(per_pixel[k].x, per_texel[k].x, 1e-5f);
        EXPECT_GT(per_pixel[k].x, 0.1f);
    }
}

TEST(PerspectiveView, PixelShadowsAreSharpWhereBlendedTexelsAreNot) {
    // A plateau 50 m high west of column 30 shades the plain east of it under a sun in the
    // west 45 degrees up (to column ~35); the texels' visible fractions, blended, make a ramp
    // a texel wide, the pixel rays a step. Seen from above, count the pixels in between.
    Scene s;
    for (int r = 0; r < s.h; ++r)
        for (int c = 0; c <= 30; ++c) s.z[std::size_t(r * s.w + c)] = 150.0f;
    s.grid = terrain::HeightGrid::uniform(s.w, s.h, s.z, 10.0, 10.0);
    PerspectiveOptions o;
    o.width = 96, o.height = 64;
    o.curvature = false;
    o.haze_distance_m = 0;
    Camera c = s.above_centre(500, -90);
    c.lon_deg += 0.0004;  // ~3 texels east: the camera over the shadow's edge
    c.fov_deg = 20;
    const PerspectiveView v(s.grid, s.georef, c, o);
    const float e = std::sqrt(0.5f);
    const glm::vec3 sun(-e, 0, e);
    // The texels' visible fractions: shaded up to column 35, lit from 36 (a hard texel step).
    std::vector<float> vis(std::size_t(s.w * s.h), 1.0f);
    for (int r = 0; r < s.h; ++r)
        for (int col = 31; col <= 35; ++col) vis[std::size_t(r * s.w + col)] = 0.0f;
    const SunFrame frame(s.grid, sun, vis);
    light::SkyTable sky(light::SkyGrid::whole_sphere(8, 4));
    std::vector<glm::vec3> marched;
    auto in_between = [&](bool per_pixel) {
        PerspectiveOptions po = o;
        po.pixel_sun_shadows = per_pixel;
        const PerspectiveView view(s.grid, s.georef, c, po);
        std::vector<glm::vec3> img;
        TexelSunTerm term = frame.term;
        term.terrain_visibility = vis.data();  // read by per-pixel shadows only
        view.compose(frame.radiance.data(), &term, sky, sun, {0, 0, 0}, std::cos(0.004654), img);
        if (per_pixel) {
            // Pixels whose texels agree take their visibility without a ray: against marching
            // every pixel (all texels marked as in a penumbra), the same picture.
            const std::vector<float> penumbra(vis.size(), 0.5f);
            term.terrain_visibility = penumbra.data();
            view.compose(frame.radiance.data(), &term, sky, sun, {0, 0, 0}, std::cos(0.004654), marched);
            for (std::size_t k = 0; k < img.size(); ++k) EXPECT_NEAR(marched[k].x, img[k].x, 1e-4f) << k;
        }
        // On level ground only: the plateau's rim is shaded by its own rounded slope.
        int count = 0, dark = 0;
        for (std::size_t k = 0; k < img.size(); ++k) {
            if (view.surface_normal(k).z < 0.9999f) continue;
            const glm::vec3& p = img[k];
            count += p.x > 0.12f && p.x < 0.43f;  // between shaded (0.1) and lit (0.1 + 0.5 e)
            dark += p.x <= 0.12f;
        }
        EXPECT_GT(dark, 100) << per_pixel;
        return count;
    };
    const int blended = in_between(false), sharp = in_between(true);
    EXPECT_GT(blended, 3 * sharp);
    EXPECT_LT(sharp, 2 * o.height);  // at most a pixel or two across the edge, per row
}

// The RMS distance of per-column values from their least-squares line, which must be slanted
// (it crosses rows).
double rms_off_a_slanted_line(const std::vector<double>& col) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const int n = int(col.size());
    for (int i = 0; i < n; ++i) sx += i, sy += col[std::size_t(i)], sxx += double(i) * i, sxy += i * col[std::size_t(i)];
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx), icpt = (sy - slope * sx) / n;
    EXPECT_GT(std::abs(slope), 0.02);
    double se = 0;
    for (int i = 0; i < n; ++i) se += std::pow(col[std::size_t(i)] - (icpt + slope * i), 2);
    return std::sqrt(se / n);
}

TEST(PerspectiveView, ASilhouetteAgainstTheSkyIsAStraightLineNotAStaircase) {
    // Looking north-north-east over the plane out of its north edge, which the picture shows as
    // a slanted straight line against the sky. Per column, the terrain's share of the pixels is
    // the edge's height there: linear in the column. With one ray per pixel it moves in whole
    // pixels (a staircase: RMS 1/sqrt(12) = 0.29 px off the line); with 4 x 4 rays across each
    // silhouette pixel it follows the line (measured: 0.289 and 0.057 px).
    Scene s;
    PerspectiveOptions o;
    o.width = 96, o.height = 24;
    o.curvature = false;
    o.haze_distance_m = 0;
    Camera c = s.above_centre(150, -9);
    c.heading_deg = 20;
    auto off_the_line = [&](int samples) {
        o.edge_samples = samples;
        const PerspectiveView v(s.grid, s.georef, c, o);
        std::vector<double> col(std::size_t(o.width), 0.0);
        for (int j = 0; j < o.height; ++j)
            for (int i = 0; i < o.width; ++i) col[std::size_t(i)] += v.terrain_coverage(std::size_t(j) * o.width + i);
        return rms_off_a_slanted_line(col);
    };
    const double one = off_the_line(1), grid = off_the_line(4);
    std::printf("skyline off a straight line: %.3f px with one ray, %.3f with 4 x 4\n", one, grid);
    EXPECT_GT(one, 0.2);
    EXPECT_LT(grid, 0.08);
}

TEST(PerspectiveView, NearTerrainAgainstFarTerrainIsAStraightLineNotAStaircase) {
    // A plateau 100 m high ends along an east-west line (row 150) above a plain that runs on
    // 1.5 km north. Seen from 50 m above the plateau, 300 m south of its edge, the edge is a
    // slanted straight line with the plain, three times farther, behind it. Per column, the
    // plateau's share of the pixels is linear in the column when the edge pixels are
    // antialiased, a staircase with one ray each.
    const int w = 64, h = 200;
    std::vector<float> z(std::size_t(w * h), 0.0f);
    for (int r = 150; r < h; ++r)
        for (int c = 0; c < w; ++c) z[std::size_t(r * w + c)] = 100.0f;
    const terrain::HeightGrid grid = terrain::HeightGrid::uniform(w, h, z, 10.0, 10.0);
    const geo::Georef georef(w, h, {500000.0, 10.0, 0.0, 5000000.0, 0.0, -10.0}, geo::Crs::from_epsg(32631), true);
    const glm::dvec2 ll = georef.pixel_to_lonlat(32.0, 180.0);
    Camera c;
    c.lon_deg = ll.x, c.lat_deg = ll.y, c.height_m = 150, c.heading_deg = 20, c.pitch_deg = -9.5, c.fov_deg = 40;
    PerspectiveOptions o;
    o.width = 96, o.height = 24;
    o.curvature = false;
    o.haze_distance_m = 0;
    auto off_the_line = [&](int samples) {
        o.edge_samples = samples;
        const PerspectiveView v(grid, georef, c, o);
        std::vector<double> col(std::size_t(o.width), 0.0);
        std::size_t plain = 0;
        for (int j = 0; j < o.height; ++j)
            for (int i = 0; i < o.width; ++i) {
                const std::size_t k = std::size_t(j) * o.width + i;
                // The plateau is the front surface within 500 m; the plain lies beyond 800 m.
                if (v.terrain_distance(k) < 500) col[std::size_t(i)] += v.front_coverage(k);
                else plain += v.terrain_distance(k) < 2000;
            }
        EXPECT_GT(plain, std::size_t(o.width * 2));  // the plain shows behind the edge
        return rms_off_a_slanted_line(col);
    };
    const double one = off_the_line(1), grid_rays = off_the_line(4);
    std::printf("near edge against far terrain off a straight line: %.3f px with one ray, %.3f with 4 x 4\n", one,
                grid_rays);
    EXPECT_GT(one, 0.2);
    EXPECT_LT(grid_rays, 0.08);
}

TEST(PerspectiveView, CameraParsing) {
    const Camera c = parse_camera("5.7,45.2,3000,90,-10,50");
    EXPECT_DOUBLE_EQ(c.lon_deg, 5.7);
    EXPECT_DOUBLE_EQ(c.fov_deg, 50);
    EXPECT_THROW(parse_camera("5.7,45.2,3000"), InputError);
    EXPECT_THROW(parse_camera("5.7,95,3000,0,0,50"), InputError);
    EXPECT_THROW(parse_camera("a,45,3000,0,0,50"), InputError);
}

}  // namespace
}  // namespace ts::render
