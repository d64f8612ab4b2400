// Placement: the attitude's conventions (heading clockwise from north, pitch nose up, roll
// right side down) and the model -> ENU transform with heights above datum or ground.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/geo/local_frame.hpp"
#include "core/mesh/placement.hpp"
#include "core/util/error.hpp"

namespace {
using ts::mesh::Placement;

void expect_vec(const glm::dvec3& a, const glm::dvec3& b, double tol = 1e-9) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TEST(Placement, HeadingTurnsForwardClockwiseFromNorth) {
    Placement p;
    p.heading_deg = 90.0;  // east
    const glm::dmat3 r = ts::mesh::placement_rotation(p);
    expect_vec(r * glm::dvec3(0, 1, 0), {1, 0, 0});
    expect_vec(r * glm::dvec3(1, 0, 0), {0, -1, 0});  // the right side now points south
    expect_vec(r * glm::dvec3(0, 0, 1), {0, 0, 1});
}

TEST(Placement, PitchLiftsTheNoseAndRollLowersTheRight) {
    Placement p;
    p.pitch_deg = 30.0;
    expect_vec(ts::mesh::placement_rotation(p) * glm::dvec3(0, 1, 0), {0, std::cos(0.5235987755982988), 0.5});
    Placement q;
    q.roll_deg = 30.0;
    const glm::dvec3 right = ts::mesh::placement_rotation(q) * glm::dvec3(1, 0, 0);
    EXPECT_NEAR(right.z, -0.5, 1e-12);
}

TEST(Placement, RotationIsProper) {
    Placement p;
    p.heading_deg = 37;
    p.pitch_deg = -12;
    p.roll_deg = 71;
    const glm::dmat3 r = ts::mesh::placement_rotation(p);
    EXPECT_NEAR(glm::determinant(r), 1.0, 1e-12);
    const glm::dmat3 i = glm::transpose(r) * r;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) EXPECT_NEAR(i[a][b], a == b ? 1.0 : 0.0, 1e-12);
}

TEST(Placement, ModelToEnuPlacesTheOriginAndScales) {
    const ts::geo::LocalFrame frame(glm::dvec3(6.0, 45.0, 200.0));
    Placement p;
    p.lon_deg = 6.0;
    p.lat_deg = 45.0;
    p.height_m = 300.0;
    p.scale = 2.0;
    const glm::dmat4 m = ts::mesh::model_to_enu(p, frame);
    expect_vec(glm::dvec3(m * glm::dvec4(0, 0, 0, 1)), {0, 0, 100}, 1e-6);
    expect_vec(glm::dvec3(m * glm::dvec4(1, 0, 0, 1)), {2, 0, 100}, 1e-6);
    p.above_ground = true;
    p.height_m = 10.0;
    const glm::dmat4 agl = ts::mesh::model_to_enu(p, frame, 250.0);  // ground at 250 m
    expect_vec(glm::dvec3(agl * glm::dvec4(0, 0, 0, 1)), {0, 0, 60}, 1e-6);
}

TEST(Placement, AbsurdValuesAreInputErrors) {
    Placement p;
    p.lat_deg = 91;
    EXPECT_THROW(ts::mesh::validate(p), ts::InputError);
    p = {};
    p.scale = 0;
    EXPECT_THROW(ts::mesh::validate(p), ts::InputError);
    p = {};
    p.heading_deg = std::nan("");
    EXPECT_THROW(ts::mesh::validate(p), ts::InputError);
}

}  // namespace
