#include "coupling_measurements.hpp"

#include "haptics/virtual_coupling.hpp"
#include "session_harness.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mssph::validation {
namespace {

constexpr double kDt = 2.5e-4;    // the scenes' step: four steps per haptic tick
constexpr double kPeriod = 1e-3;  // 1 kHz haptic loop (the default)
constexpr double kZeta = 0.3;     // damping ratio of the step responses
constexpr double kOmega = 20.0;   // natural frequency of the step responses [rad/s]

// Peak overshoot of a damped oscillator's step response, as a fraction of the step.
double predicted_overshoot(double zeta) { return std::exp(-std::numbers::pi * zeta / std::sqrt(1.0 - zeta * zeta)); }

void predict(StepResponse& r, double stiffness, double damping, double inertia) {
  const double zeta_held = (damping - 0.5 * stiffness * kPeriod) / (2.0 * std::sqrt(stiffness * inertia));
  r.predicted_low = predicted_overshoot(kZeta);
  r.predicted_high = predicted_overshoot(zeta_held);
}

}  // namespace

HapticsConfig held_device(const Pose& pose, const SpringDamperGains& gains) {
  HapticsConfig config;
  config.coupling = gains;
  config.trajectory.source = TrajectorySource::recorded;
  config.trajectory.recording = DeviceRecording{{0.0}, {pose}};
  return config;
}

StepResponse translation_step_response() {
  const double mass = 1.0;
  const double stiffness = kOmega * kOmega * mass;                   // 400 N/m
  const double damping = 2.0 * kZeta * std::sqrt(stiffness * mass);  // 12 N s/m
  const double step = 0.05;
  Pose device;
  device.position = Eigen::Vector3d(step, 0.0, 0.0);
  test::RigidBodyDouble body(mass, 1.0, kDt);
  const auto samples =
      test::run_session(held_device(device, {stiffness, damping, 0.0, 0.0}), body, mass, 1.0, kDt, 2.0);
  StepResponse r;
  double peak = 0.0;
  for (const HapticSample& s : samples) {
    peak = std::max(peak, s.proxy_pose.position.x());
    r.time.push_back(s.time);
    r.response.push_back(s.proxy_pose.position.x());
  }
  r.overshoot = (peak - step) / step;
  r.final_error = std::abs(samples.back().proxy_pose.position.x() - step) / step;
  r.off_axis = std::abs(samples.back().proxy_pose.position.y());
  predict(r, stiffness, damping, mass);
  return r;
}

StepResponse rotation_step_response() {
  const double inertia = 1e-3;
  const double stiffness = kOmega * kOmega * inertia;                   // 0.4 N m/rad
  const double damping = 2.0 * kZeta * std::sqrt(stiffness * inertia);  // 0.012 N m s/rad
  const double angle = 0.5;
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 1.0, 0.0).normalized();
  Pose device;
  device.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis));
  test::RigidBodyDouble body(1.0, inertia, kDt);
  const auto samples =
      test::run_session(held_device(device, {0.0, 0.0, stiffness, damping}), body, 1.0, inertia, kDt, 2.0);
  StepResponse r;
  double peak = 0.0;
  for (const HapticSample& s : samples) {
    const double turned = rotation_vector(s.proxy_pose.orientation).dot(axis);
    peak = std::max(peak, turned);
    r.time.push_back(s.time);
    r.response.push_back(turned);
  }
  r.overshoot = (peak - angle) / angle;
  r.final_error = samples.back().proxy_pose.orientation.angularDistance(device.orientation) / angle;
  predict(r, stiffness, damping, inertia);
  return r;
}

HapticsConfig five_second_script(const SpringDamperGains& coupling) {
  HapticsConfig config;
  config.coupling = coupling;
  config.trajectory.source = TrajectorySource::scripted;
  const auto turn = [](double degrees) {
    return Eigen::Quaterniond(
        Eigen::AngleAxisd(degrees * std::numbers::pi / 180.0, Eigen::Vector3d(0.3, 0.2, 1.0).normalized()));
  };
  config.trajectory.keyframes = {{0.0, Pose{Eigen::Vector3d::Zero(), turn(0)}},
                                 {0.6, Pose{Eigen::Vector3d(0.1, 0.0, 0.0), turn(30)}},
                                 {1.0, Pose{Eigen::Vector3d(0.1, 0.0, -0.08), turn(30)}},
                                 {1.5, Pose{Eigen::Vector3d(0.1, 0.0, -0.08), turn(-20)}},
                                 {1.8, Pose{Eigen::Vector3d(0.1, 0.05, 0.0), turn(-20)}},
                                 {2.2, Pose{Eigen::Vector3d(0.0, 0.05, -0.08), turn(60)}},
                                 {2.4, Pose{Eigen::Vector3d(0.0, 0.05, 0.02), turn(0)}},
                                 {3.5, Pose{Eigen::Vector3d(-0.1, -0.1, 0.0), turn(-45)}},
                                 {4.0, Pose{Eigen::Vector3d(-0.1, -0.1, -0.08), turn(-45)}},
                                 {4.5, Pose{Eigen::Vector3d::Zero(), turn(0)}}};
  return config;
}

PassivityMeasurement passivity_over_script(const SpringDamperGains& coupling, double stop_above) {
  const double mass = 1.0;
  const double inertia = 1e-2;
  test::RigidBodyDouble body(mass, inertia, kDt);
  body.floor = test::Floor{-0.05, 2e4, 50.0};  // 5 cm below the start: reached by the 8 cm taps
  const auto samples = test::run_session(five_second_script(coupling), body, mass, inertia, kDt, 5.0,
                                         [&](const HapticSample& s) { return s.injected_energy > stop_above; });
  PassivityMeasurement m;
  m.ticks = samples.size();
  for (const HapticSample& s : samples) {
    m.max_injected = std::max(m.max_injected, s.injected_energy);
    m.deepest = std::min(m.deepest, s.proxy_pose.position.z());
    m.peak_force = std::max(m.peak_force, s.interaction.force.z());
    m.time.push_back(s.time);
    m.injected.push_back(s.injected_energy);
  }
  m.final_injected = samples.back().injected_energy;
  m.end_time = samples.back().time;
  return m;
}

}  // namespace mssph::validation
