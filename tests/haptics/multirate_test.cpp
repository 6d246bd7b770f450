// The haptic loop against simulation steps shorter and longer than its period: tick times,
// state queries, the wrench the proxy receives, the local model between steps, determinism.
#include "physics/coupling/session_harness.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <ostream>

namespace mssph::test {
namespace {

constexpr double kPeriod = 1e-3;  // 1 kHz haptic loop (the default)

HapticsConfig scripted_reach() {
  HapticsConfig config;
  config.trajectory.source = TrajectorySource::scripted;
  const Eigen::Quaterniond turned(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitY()));
  config.trajectory.keyframes = {{0.0, Pose{}},
                                 {0.2, Pose{Eigen::Vector3d(0.05, 0.0, 0.0), turned}},
                                 {0.4, Pose{Eigen::Vector3d(0.05, 0.03, -0.02), Eigen::Quaterniond::Identity()}}};
  return config;
}

struct LoopCase {
  double dt;
  const char* name;
};

// Names the case in test listings (ctest shows parameters).
void PrintTo(const LoopCase& c, std::ostream* out) { *out << c.name << " (dt = " << c.dt << " s)"; }

class HapticLoopAtStep : public ::testing::TestWithParam<LoopCase> {};

TEST_P(HapticLoopAtStep, TicksAtTheHapticRateWithOneStateQueryPerTickAtMost) {
  const double dt = GetParam().dt;
  const double duration = 1.0;
  RigidBodyDouble body(1.0, 1e-2, dt);
  const auto samples = run_session(scripted_reach(), body, 1.0, 1e-2, dt, duration);

  // Ticks at 0, T, 2T, ... up to the end of the last whole step (0.9999 s for dt = 0.3 ms).
  const auto ticks = static_cast<std::size_t>(std::floor(body.time() / kPeriod + 1e-9)) + 1;
  ASSERT_EQ(samples.size(), ticks);
  for (std::size_t n = 0; n < ticks; ++n) ASSERT_EQ(samples[n].time, static_cast<double>(n) * kPeriod);
  EXPECT_LE(body.state_queries, ticks);
  EXPECT_GE(body.state_queries, 1u);
  // The hand brought the handle to the last keyframe: 0.6 s later, only the proxy's slowly decaying
  // swing on the coupling (damping ratio 0.16) still moves it, by a fraction of a millimetre.
  EXPECT_LT((samples.back().device_pose.position - Eigen::Vector3d(0.05, 0.03, -0.02)).norm(), 1e-3);
}

TEST_P(HapticLoopAtStep, ProxyReceivesTheImpulseOfEveryTickHeldUntilTheNext) {
  const double dt = GetParam().dt;
  const double duration = 0.5;
  RigidBodyDouble body(1.0, 1e-2, dt);
  const auto samples = run_session(scripted_reach(), body, 1.0, 1e-2, dt, duration);
  const double end = body.time();  // whole steps: 0.5001 s for dt = 0.3 ms

  // The coupling force is piecewise constant from tick to tick; the steps together must apply
  // its integral over the run, however ticks and steps interleave.
  Eigen::Vector3d expected = Eigen::Vector3d::Zero();
  double scale = 0.0;
  for (std::size_t n = 0; n < samples.size(); ++n) {
    const double held = (n + 1 < samples.size() ? samples[n + 1].time : end) - samples[n].time;
    expected += samples[n].coupling.force * held;
    scale += samples[n].coupling.force.norm() * held;
  }
  // Sums of 500 terms in a different order: rounding of 1e-12 of the total magnitude.
  EXPECT_LT((body.applied_impulse - expected).norm(), 1e-12 * scale + 1e-300);
  EXPECT_GT(scale, 1e-3);  // the coupling did pull
}

INSTANTIATE_TEST_SUITE_P(Steps, HapticLoopAtStep,
                         ::testing::Values(LoopCase{2.5e-4, "FourStepsPerTick"}, LoopCase{3e-4, "MisalignedShortSteps"},
                                           LoopCase{2.5e-3, "TwoAndAHalfTicksPerStep"}),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(HapticLoop, AlignedStepsQueryTheProxyExactlyOncePerTickAndHoldItsWrench) {
  const double dt = 2.5e-4;
  RigidBodyDouble body(1.0, 1e-2, dt);
  const auto samples = run_session(scripted_reach(), body, 1.0, 1e-2, dt, 0.5);
  EXPECT_EQ(body.state_queries, samples.size());
  EXPECT_LE(body.wrench_updates, samples.size());  // set at ticks only, never per step
}

TEST(HapticLoop, StepsLongerThanTheHapticPeriodStillSettleTheProxy) {
  const double dt = 2.5e-3;
  for (const BetweenSteps mode : {BetweenSteps::hold, BetweenSteps::linearised}) {
    HapticsConfig config = scripted_reach();
    config.between_steps = mode;
    RigidBodyDouble body(1.0, 1e-2, dt);
    const auto samples = run_session(config, body, 1.0, 1e-2, dt, 1.5);
    // A second after the script ends, proxy and handle rest at the last keyframe (no gravity,
    // so every spring relaxes); the query at the end time returns the simulated state itself.
    const HapticSample& last = samples.back();
    EXPECT_LT((last.proxy_pose.position - body.pose.position).norm(), 1e-12);
    EXPECT_LT(last.proxy_twist.linear.norm(), 1e-3);
    EXPECT_LT((last.proxy_pose.position - Eigen::Vector3d(0.05, 0.03, -0.02)).norm(), 5e-3);
  }
}

TEST(HapticLoop, LinearisedModelCarriesTheProxyBetweenStepsWhereHoldKeepsItsLastState) {
  // A proxy coasting at 0.1 m/s with no coupling (zero gains): between steps four ticks long,
  // the linearised model extrapolates its motion exactly, hold lags by up to three ticks.
  const double dt = 4e-3;
  const Eigen::Vector3d velocity(0.1, 0.0, 0.0);
  double largest_lag[2] = {0.0, 0.0};
  for (const BetweenSteps mode : {BetweenSteps::hold, BetweenSteps::linearised}) {
    HapticsConfig config;
    config.coupling = SpringDamperGains{};
    config.between_steps = mode;
    RigidBodyDouble body(1.0, 1e-2, dt);
    body.twist.linear = velocity;
    const auto samples = run_session(config, body, 1.0, 1e-2, dt, 0.1);
    for (const HapticSample& s : samples) {
      const double lag = (velocity * s.time - s.proxy_pose.position).norm();
      largest_lag[mode == BetweenSteps::hold ? 0 : 1] = std::max(largest_lag[mode == BetweenSteps::hold ? 0 : 1], lag);
    }
  }
  EXPECT_NEAR(largest_lag[0], 3.0 * kPeriod * velocity.norm(), 1e-12);  // the tick 3 ms into a step
  EXPECT_LT(largest_lag[1], 1e-15);                                     // exact up to rounding
}

TEST(HapticLoop, RunsAreDeterministicInSimulatedTime) {
  const auto run = [] {
    RigidBodyDouble body(1.0, 1e-2, 3e-4);
    return run_session(scripted_reach(), body, 1.0, 1e-2, 3e-4, 0.3);
  };
  const auto a = run();
  const auto b = run();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t n = 0; n < a.size(); ++n) {
    ASSERT_EQ(a[n].device_pose.position, b[n].device_pose.position);
    ASSERT_EQ(a[n].proxy_pose.position, b[n].proxy_pose.position);
    ASSERT_EQ(a[n].proxy_pose.orientation.coeffs(), b[n].proxy_pose.orientation.coeffs());
    ASSERT_EQ(a[n].rendered.force, b[n].rendered.force);
    ASSERT_EQ(a[n].injected_energy, b[n].injected_energy);
  }
}

}  // namespace
}  // namespace mssph::test
