// The virtual coupling moving a free proxy (the rigid-body double) towards a device held at a
// new pose: a damped oscillator whose overshoot the damping ratio predicts.
#include "haptics/virtual_coupling.hpp"
#include "physics/coupling/coupling_measurements.hpp"
#include "physics/coupling/session_harness.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mssph::test {
namespace {

constexpr double kDt = 2.5e-4;   // the scenes' step: four steps per haptic tick
constexpr double kOmega = 20.0;  // natural frequency of the coupling [rad/s]

using validation::held_device;

// The step responses are the physics case's (validation/physics/coupling_step). The coupling
// wrench is held for a haptic period T: a zero-order hold delays it by T/2, which acts as a
// negative damping K T / 2 (Colgate et al. 1995). The loop's damping ratio therefore lies between
// zeta (continuous) and (B - K T / 2) / (2 sqrt(K m)); 1 % on either side covers the
// O((omega T)^2) = 4e-4 terms the half-period model leaves out and sampling the peak at ticks.
void expect_overshoot_of_damping_ratio(const validation::StepResponse& r) {
  ::testing::Test::RecordProperty("overshoot", std::to_string(r.overshoot));
  ::testing::Test::RecordProperty("predicted_overshoot_range",
                                  std::to_string(r.predicted_low) + " to " + std::to_string(r.predicted_high));
  EXPECT_GE(r.overshoot, 0.99 * r.predicted_low);
  EXPECT_LE(r.overshoot, 1.01 * r.predicted_high);
}

TEST(CouplingStepResponse, ProxyFollowsATranslationStepAndSettlesWithThePredictedOvershoot) {
  const validation::StepResponse r = validation::translation_step_response();
  expect_overshoot_of_damping_ratio(r);
  // After 2 s the envelope exp(-zeta omega t) is 6e-6: 1e-4 of the step leaves room for the
  // discrete loop's slightly lower damping.
  EXPECT_LT(r.final_error, 1e-4);
  EXPECT_LT(r.off_axis, 1e-12);  // nothing pushes it sideways
}

TEST(CouplingStepResponse, ProxyFollowsARotationStepAndSettlesWithThePredictedOvershoot) {
  const validation::StepResponse r = validation::rotation_step_response();
  expect_overshoot_of_damping_ratio(r);
  EXPECT_LT(r.final_error, 1e-4);
}

TEST(CouplingStepResponse, RotationErrorPast180DegreesTurnsTheProxyTheShortWay) {
  // The device is 190 degrees about +z from the proxy: the short way is 170 degrees about -z.
  const double inertia = 1e-3;
  const double stiffness = kOmega * kOmega * inertia;
  const double damping = 2.0 * std::sqrt(stiffness * inertia);  // critical: no overshoot to wrap around
  const double target = 190.0 * std::numbers::pi / 180.0;
  Pose device;
  device.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(target, Eigen::Vector3d::UnitZ()));
  RigidBodyDouble body(1.0, inertia, kDt);
  const auto samples = run_session(held_device(device, {0.0, 0.0, stiffness, damping}), body, 1.0, inertia, kDt, 2.0);

  const double short_way = target - 2.0 * std::numbers::pi;  // -170 degrees
  for (const HapticSample& s : samples) {
    const double turned = rotation_vector(s.proxy_pose.orientation).z();
    // Monotonic from 0 to -170 degrees: never positive, never past the target (1e-9 rad: rounding).
    ASSERT_LE(turned, 1e-9) << "turned the long way at t = " << s.time;
    ASSERT_GE(turned, short_way - 1e-9) << "overshot at t = " << s.time;
  }
  EXPECT_LT(samples[1].proxy_twist.angular.z(), 0.0);
  // Critically damped, the error after 2 s is (1 + omega t) exp(-omega t) = 2e-16 of the step.
  EXPECT_LT(samples.back().proxy_pose.orientation.angularDistance(device.orientation), 1e-6);
}

}  // namespace
}  // namespace mssph::test
