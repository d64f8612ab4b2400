#include "core/fly/grid_frame.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace ts::fly {
namespace {

TEST(GridFrame, UniformGridIsCentredAndInvertible) {
    std::vector<float> z(11 * 7, 0.0f);
    const terrain::HeightGrid g = terrain::HeightGrid::uniform(11, 7, z, 30.0, 20.0);
    const GridFrame f(g);
    const glm::dvec2 c = f.to_metric(5.0, 3.0);
    EXPECT_NEAR(c.x, 0.0, 1e-9);
    EXPECT_NEAR(c.y, 0.0, 1e-9);
    const glm::dvec2 ne = f.to_metric(10.0, 0.0);
    EXPECT_NEAR(ne.x, 150.0, 1e-9);
    EXPECT_NEAR(ne.y, 60.0, 1e-9);  // row 0 is north
    const glm::dvec2 back = f.to_grid(ne.x, ne.y);
    EXPECT_NEAR(back.x, 10.0, 1e-6);
    EXPECT_NEAR(back.y, 0.0, 1e-6);
}

TEST(GridFrame, PerRowSpacingNarrowsEastWest) {
    std::vector<float> z(5 * 3, 0.0f);
    terrain::HeightGrid g = terrain::HeightGrid::uniform(5, 3, z, 30.0, 30.0);
    g.dx_m = {20.0, 25.0, 30.0};  // narrower to the north
    const GridFrame f(g);
    EXPECT_NEAR(f.to_metric(4.0, 0.0).x, 40.0, 1e-9);
    EXPECT_NEAR(f.to_metric(4.0, 2.0).x, 60.0, 1e-9);
    EXPECT_NEAR(f.to_metric(4.0, 0.5).x, 45.0, 1e-9);  // interpolated between rows
    const glm::dvec2 g2 = f.to_grid(45.0, f.north_at(0.5));
    EXPECT_NEAR(g2.x, 4.0, 1e-6);
    EXPECT_NEAR(g2.y, 0.5, 1e-6);
}

}  // namespace
}  // namespace ts::fly
