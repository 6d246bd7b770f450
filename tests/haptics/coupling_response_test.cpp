// The virtual coupling moving a free proxy (the rigid-body double) towards a device held at a
// new pose: a damped oscillator whose overshoot the damping ratio predicts.
#include "haptics/virtual_coupling.hpp"
#include "session_harness.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mssph::test {
namespace {

constexpr double kDt = 2.5e-4;    // the scenes' step: four steps per haptic tick
constexpr double kPeriod = 1e-3;  // 1 kHz haptic loop (the default)
constexpr double kZeta = 0.3;     // damping ratio of the step responses
constexpr double kOmega = 20.0;   // natural frequency of the step responses [rad/s]

// A device held still at `pose`: a one-sample recording (the handle does not move).
HapticsConfig held_device(const Pose& pose, const SpringDamperGains& gains) {
  HapticsConfig config;
  config.coupling = gains;
  config.trajectory.source = TrajectorySource::recorded;
  config.trajectory.recording = DeviceRecording{{0.0}, {pose}};
  return config;
}

// Peak overshoot of a damped oscillator's step response, as a fraction of the step.
double predicted_overshoot(double zeta) { return std::exp(-std::numbers::pi * zeta / std::sqrt(1.0 - zeta * zeta)); }

// The coupling wrench is held for a haptic period T: a zero-order hold delays it by T/2, which
// acts as a negative damping K T / 2 (Colgate et al. 1995). The loop's damping ratio therefore
// lies between zeta (continuous) and (B - K T / 2) / (2 sqrt(K m)); 1 % on either side covers
// the O((omega T)^2) = 4e-4 terms the half-period model leaves out and sampling the peak at ticks.
void expect_overshoot_of_damping_ratio(double overshoot, double stiffness, double damping, double inertia) {
  const double zeta_held = (damping - 0.5 * stiffness * kPeriod) / (2.0 * std::sqrt(stiffness * inertia));
  ::testing::Test::RecordProperty("overshoot", std::to_string(overshoot));
  ::testing::Test::RecordProperty("predicted_overshoot_range", std::to_string(predicted_overshoot(kZeta)) + " to " +
                                                                   std::to_string(predicted_overshoot(zeta_held)));
  EXPECT_GE(overshoot, 0.99 * predicted_overshoot(kZeta));
  EXPECT_LE(overshoot, 1.01 * predicted_overshoot(zeta_held));
}

TEST(CouplingStepResponse, ProxyFollowsATranslationStepAndSettlesWithThePredictedOvershoot) {
  const double mass = 1.0;
  const double stiffness = kOmega * kOmega * mass;                   // 400 N/m
  const double damping = 2.0 * kZeta * std::sqrt(stiffness * mass);  // 12 N s/m
  const double step = 0.05;
  Pose device;
  device.position = Eigen::Vector3d(step, 0.0, 0.0);
  RigidBodyDouble body(mass, 1.0, kDt);
  const auto samples = run_session(held_device(device, {stiffness, damping, 0.0, 0.0}), body, mass, 1.0, kDt, 2.0);

  double peak = 0.0;
  for (const HapticSample& s : samples) peak = std::max(peak, s.proxy_pose.position.x());
  expect_overshoot_of_damping_ratio((peak - step) / step, stiffness, damping, mass);
  // After 2 s the envelope exp(-zeta omega t) is 6e-6: 1e-4 of the step leaves room for the
  // discrete loop's slightly lower damping.
  EXPECT_NEAR(samples.back().proxy_pose.position.x(), step, 1e-4 * step);
  EXPECT_NEAR(samples.back().proxy_pose.position.y(), 0.0, 1e-12);  // nothing pushes it sideways
}

TEST(CouplingStepResponse, ProxyFollowsARotationStepAndSettlesWithThePredictedOvershoot) {
  const double inertia = 1e-3;
  const double stiffness = kOmega * kOmega * inertia;                   // 0.4 N m/rad
  const double damping = 2.0 * kZeta * std::sqrt(stiffness * inertia);  // 0.012 N m s/rad
  const double angle = 0.5;
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 1.0, 0.0).normalized();
  Pose device;
  device.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis));
  RigidBodyDouble body(1.0, inertia, kDt);
  const auto samples = run_session(held_device(device, {0.0, 0.0, stiffness, damping}), body, 1.0, inertia, kDt, 2.0);

  double peak = 0.0;
  for (const HapticSample& s : samples) peak = std::max(peak, rotation_vector(s.proxy_pose.orientation).dot(axis));
  expect_overshoot_of_damping_ratio((peak - angle) / angle, stiffness, damping, inertia);
  EXPECT_LT(samples.back().proxy_pose.orientation.angularDistance(device.orientation), 1e-4 * angle);
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
