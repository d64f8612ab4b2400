#include "core/fly/fly_camera.hpp"

#include <gtest/gtest.h>

#include "core/fly/camera_rig.hpp"
#include "core/util/angles.hpp"

#include <cmath>
#include <glm/geometric.hpp>

namespace ts::fly {
namespace {

glm::dvec3 ndc(const glm::dmat4& m, const glm::dvec3& p) {
    const glm::dvec4 c = m * glm::dvec4(p, 1.0);
    return glm::dvec3(c) / c.w;
}

TEST(FlyCamera, ForwardPointProjectsToTheCentreWithReversedDepth) {
    CameraPose pose;
    pose.heading_deg = 90;  // east
    Projection proj;
    const glm::dmat4 vp = eye_relative_view_projection(pose, proj);
    const glm::dvec3 centre = ndc(vp, {100.0, 0.0, 0.0});
    EXPECT_NEAR(centre.x, 0.0, 1e-12);
    EXPECT_NEAR(centre.y, 0.0, 1e-12);
    EXPECT_NEAR(centre.z, proj.near_m / 100.0, 1e-12);  // reversed Z: near / distance
    EXPECT_LT(ndc(vp, {1000.0, 0.0, 0.0}).z, centre.z);
    // North is to the left when looking east; up is up (Vulkan NDC y points down).
    EXPECT_LT(ndc(vp, {100.0, 10.0, 0.0}).x, 0.0);
    EXPECT_LT(ndc(vp, {100.0, 0.0, 10.0}).y, 0.0);
    // The edge of the horizontal field of view lands on x = 1.
    EXPECT_NEAR(ndc(vp, {100.0, -100.0 * std::tan(radians(30.0)), 0.0}).x, 1.0, 1e-12);
}

TEST(FlyCamera, RollLowersTheRightWing) {
    const CameraAxes a = camera_axes(0.0, 0.0, 30.0);
    EXPECT_LT(a.right.z, 0.0);
    EXPECT_NEAR(glm::dot(a.right, a.forward), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(a.up, a.forward), 0.0, 1e-12);
}

TEST(FlyCamera, ChaseLooksAtTheAircraftFromBehind) {
    CameraPose aircraft;
    aircraft.eye = {1000.0, 2000.0, 1500.0};
    aircraft.heading_deg = 0;  // north
    const CameraPose c = chase_pose(aircraft, {100.0, 20.0});
    EXPECT_NEAR(c.eye.y, 1900.0, 1e-9);
    EXPECT_NEAR(c.eye.z, 1520.0, 1e-9);
    EXPECT_NEAR(c.heading_deg, 0.0, 1e-9);
    EXPECT_LT(c.pitch_deg, 0.0);
}

}  // namespace
}  // namespace ts::fly
