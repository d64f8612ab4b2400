// The one place user-facing azimuths (degrees clockwise from north) meet the internal phi
// (radians counter-clockwise from east): core/geo/azimuth.hpp.
#include "core/geo/azimuth.hpp"
#include "core/util/angles.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace ts::geo {
namespace {

TEST(Azimuth, ClockwiseFromNorthToPhi) {
    EXPECT_NEAR(azimuth_cw_from_north_to_phi(0), kPi / 2, 1e-15);   // north = +y
    EXPECT_NEAR(azimuth_cw_from_north_to_phi(90), 0, 1e-15);                     // east = +x
    EXPECT_NEAR(std::cos(azimuth_cw_from_north_to_phi(180)), 0, 1e-15);
    EXPECT_NEAR(std::sin(azimuth_cw_from_north_to_phi(180)), -1, 1e-15);         // south = -y
    EXPECT_NEAR(std::cos(azimuth_cw_from_north_to_phi(270)), -1, 1e-15);         // west = -x
    for (double az : {0.0, 10.0, 135.0, 315.0, 359.5}) EXPECT_NEAR(phi_to_azimuth_cw_from_north(azimuth_cw_from_north_to_phi(az)), az, 1e-12);
    const glm::dvec3 nw = enu_direction(azimuth_cw_from_north_to_phi(315), 0);
    EXPECT_LT(nw.x, 0);
    EXPECT_GT(nw.y, 0);
}

}  // namespace
}  // namespace ts::geo
