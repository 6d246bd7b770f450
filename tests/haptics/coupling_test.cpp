// The pieces of the haptic loop on their own: the coupling's wrench, the device's rendering and
// motion, the workspace map and the pose tracks.
#include "haptics/device_model.hpp"
#include "haptics/pose_track.hpp"
#include "haptics/virtual_coupling.hpp"
#include "haptics/workspace_transform.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace mssph {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

Eigen::Quaterniond about_z(double degrees) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(degrees * kDegree, Eigen::Vector3d::UnitZ()));
}

TEST(OrientationError, TakesTheShortWayPast180Degrees) {
  // 190 degrees about +z is 170 degrees about -z, whichever sign the quaternion carries.
  const Eigen::Quaterniond q = about_z(190.0);
  ASSERT_LT(q.w(), 0.0);
  const Eigen::Quaterniond negated(-q.w(), -q.x(), -q.y(), -q.z());
  for (const Eigen::Quaterniond& target : {q, negated}) {
    const Eigen::Vector3d error = orientation_error(target, Eigen::Quaterniond::Identity());
    EXPECT_NEAR(error.z(), -170.0 * kDegree, 1e-12);
    EXPECT_NEAR(error.head<2>().norm(), 0.0, 1e-12);
  }
  // Just short of 180 degrees the error keeps its direction.
  EXPECT_NEAR(orientation_error(about_z(179.0), Eigen::Quaterniond::Identity()).z(), 179.0 * kDegree, 1e-12);
  // The error is q_d conj(q): relative to a turned follower.
  EXPECT_NEAR(orientation_error(about_z(100.0), about_z(-100.0)).z(), -160.0 * kDegree, 1e-12);
}

TEST(OrientationError, SmallAnglesKeepFullPrecision) {
  const Eigen::Quaterniond tiny(Eigen::AngleAxisd(1e-9, Eigen::Vector3d::UnitX()));
  EXPECT_NEAR(orientation_error(tiny, Eigen::Quaterniond::Identity()).x(), 1e-9, 1e-22);
}

TEST(SpringDamperWrench, IsColgatesCouplingOnEachAxis) {
  const SpringDamperGains gains{1000.0, 10.0, 20.0, 0.5};
  const Pose target{Eigen::Vector3d(0.01, -0.02, 0.0), about_z(10.0)};
  const Twist target_twist{Eigen::Vector3d(0.1, 0.0, 0.0), Eigen::Vector3d(0.0, 0.0, 1.0)};
  const Pose follower{Eigen::Vector3d(0.0, 0.0, 0.005), Eigen::Quaterniond::Identity()};
  const Twist follower_twist{Eigen::Vector3d(0.0, 0.2, 0.0), Eigen::Vector3d(0.0, 0.0, -1.0)};
  const Wrench w = spring_damper_wrench(gains, target, target_twist, follower, follower_twist);
  EXPECT_NEAR(w.force.x(), 1000.0 * 0.01 + 10.0 * 0.1, 1e-12);
  EXPECT_NEAR(w.force.y(), 1000.0 * -0.02 + 10.0 * -0.2, 1e-12);
  EXPECT_NEAR(w.force.z(), 1000.0 * -0.005, 1e-12);
  EXPECT_NEAR(w.torque.z(), 20.0 * 10.0 * kDegree + 0.5 * 2.0, 1e-12);
}

TEST(DeviceRendering, RendersTheReactionScaledAndClampedWithItsDirection) {
  DeviceConfig config;  // 30 N, 3 N m
  config.force_scale = 0.5;
  const WorkspaceTransform turned(1.0, Eigen::Vector3d::Zero(), about_z(90.0));
  const DeviceModel device(config);

  const RenderedWrench small =
      device.render(Wrench{Eigen::Vector3d(10.0, 0.0, 0.0), Eigen::Vector3d(0.0, 0.0, 1.0)}, turned);
  // -F = (-10, 0, 0) in the scene is (0, 10, 0) in a device frame turned 90 degrees; times 0.5.
  EXPECT_NEAR((small.wrench.force - Eigen::Vector3d(0.0, 5.0, 0.0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((small.wrench.torque - Eigen::Vector3d(0.0, 0.0, -1.0)).norm(), 0.0, 1e-12);
  EXPECT_FALSE(small.force_saturated);
  EXPECT_FALSE(small.torque_saturated);

  const RenderedWrench big =
      device.render(Wrench{Eigen::Vector3d(0.0, 60.0, 80.0), Eigen::Vector3d(4.0, 0.0, 3.0)}, turned);
  EXPECT_NEAR(big.wrench.force.norm(), 30.0, 1e-12);  // 50 N after scaling, clamped to 30 N
  EXPECT_NEAR(big.wrench.force.normalized().dot(turned.direction_to_device(Eigen::Vector3d(0.0, -0.6, -0.8))), 1.0,
              1e-12);
  EXPECT_NEAR(big.wrench.torque.norm(), 3.0, 1e-12);  // 5 N m clamped to 3 N m
  EXPECT_TRUE(big.force_saturated);
  EXPECT_TRUE(big.torque_saturated);
}

TEST(DeviceMotion, StopsAtTheWorkspaceBoundary) {
  DeviceConfig config;
  config.workspace_radius = 0.1;
  const DeviceModel device(config);
  DeviceState state;
  state.pose.position = Eigen::Vector3d(0.099, 0.0, 0.0);
  state.twist.linear = Eigen::Vector3d(1.0, 0.5, 0.0);
  EXPECT_TRUE(device.advance(state, Wrench{}, 0.01));
  EXPECT_NEAR(state.pose.position.norm(), 0.1, 1e-15);
  EXPECT_LE(state.twist.linear.dot(state.pose.position), 0.0);  // no outward velocity left
  EXPECT_GT(state.twist.linear.y(), 0.0);                       // sliding along the boundary
}

TEST(DeviceMotion, HandleUnderAConstantForceAccelerates) {
  DeviceConfig config;
  config.linear_damping = 0.0;
  const DeviceModel device(config);
  DeviceState state;
  // Semi-implicit Euler: after one step v = F/m dt and x = v dt.
  EXPECT_FALSE(device.advance(state, Wrench{Eigen::Vector3d(0.0, 0.0, 2.0), Eigen::Vector3d::Zero()}, 1e-3));
  EXPECT_NEAR(state.twist.linear.z(), 2.0 / config.mass * 1e-3, 1e-15);
  EXPECT_NEAR(state.pose.position.z(), 2.0 / config.mass * 1e-6, 1e-18);
}

TEST(WorkspaceTransform, MapsDevicePosesIntoTheSceneAndBack) {
  const WorkspaceTransform map(2.0, Eigen::Vector3d(0.0, 0.0, 0.5), about_z(90.0));
  const Pose device{Eigen::Vector3d(0.1, 0.0, 0.0), about_z(30.0)};
  const Pose scene = map.to_scene(device);
  EXPECT_NEAR((scene.position - Eigen::Vector3d(0.0, 0.2, 0.5)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(scene.orientation.angularDistance(about_z(120.0)), 0.0, 1e-12);
  const Pose back = map.to_device(scene);
  EXPECT_NEAR((back.position - device.position).norm(), 0.0, 1e-15);
  EXPECT_NEAR(back.orientation.angularDistance(device.orientation), 0.0, 1e-12);
  const Twist v = map.to_scene(Twist{Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d(0.0, 0.0, 1.0)});
  EXPECT_NEAR((v.linear - Eigen::Vector3d(0.0, 2.0, 0.0)).norm(), 0.0, 1e-15);   // scaled and turned
  EXPECT_NEAR((v.angular - Eigen::Vector3d(0.0, 0.0, 1.0)).norm(), 0.0, 1e-15);  // turned only
}

TEST(PoseTrack, InterpolatesLinearlyAndBySlerpAndHoldsAtTheEnds) {
  const PoseTrack track(
      {1.0, 2.0}, {Pose{Eigen::Vector3d::Zero(), about_z(0.0)}, Pose{Eigen::Vector3d(0.2, 0.0, 0.0), about_z(90.0)}});
  const PoseTrack::Sample middle = track.at(1.25);
  EXPECT_NEAR(middle.pose.position.x(), 0.05, 1e-15);
  EXPECT_NEAR(middle.pose.orientation.angularDistance(about_z(22.5)), 0.0, 1e-12);
  EXPECT_NEAR(middle.twist.linear.x(), 0.2, 1e-15);
  EXPECT_NEAR(middle.twist.angular.z(), 90.0 * kDegree, 1e-12);
  EXPECT_EQ(track.at(0.0).pose.position, Eigen::Vector3d::Zero());
  EXPECT_EQ(track.at(0.0).twist.linear, Eigen::Vector3d::Zero());
  EXPECT_EQ(track.at(3.0).pose.position, Eigen::Vector3d(0.2, 0.0, 0.0));
  EXPECT_EQ(track.at(1.0).pose.position, Eigen::Vector3d::Zero());  // a sample time gives its pose exactly
}

TEST(PoseTrack, SlerpsTheShortWay) {
  const PoseTrack track({0.0, 1.0},
                        {Pose{Eigen::Vector3d::Zero(), about_z(0.0)}, Pose{Eigen::Vector3d::Zero(), about_z(270.0)}});
  EXPECT_NEAR(track.at(0.5).pose.orientation.angularDistance(about_z(-45.0)), 0.0, 1e-12);
  EXPECT_NEAR(track.at(0.5).twist.angular.z(), -90.0 * kDegree, 1e-12);
}

}  // namespace
}  // namespace mssph
