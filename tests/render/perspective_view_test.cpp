#include <cmath>
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
    v.compose(rad.data(), sky, {0, 0, 1}, {0, 0, 0}, 1.0, img);
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
    v.compose(rad.data(), sky, {0, 0, 1}, {0, 0, 0}, 1.0, img);
    EXPECT_GT(img[0].x, 19.0f);  // on the ridge's south face (rows 20..21), not beyond it
    EXPECT_LT(img[0].x, 21.5f);
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
