// Passivity of the virtual coupling (Colgate et al. 1995) measured by its passivity observer
// (Hannaford and Ryu 2002): over a scripted interaction the coupling may store and dissipate
// energy but never inject it, unless its gains break the explicit stability bound, which the
// start-up check then reports.
#include "haptics/coupling_stability.hpp"
#include "physics/coupling/coupling_measurements.hpp"
#include "physics/coupling/session_harness.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mssph::test {
namespace {

constexpr double kSceneDt = 2.5e-4;  // the scenes' step
constexpr double kMass = 1.0;        // proxy [kg]
constexpr double kInertia = 1e-2;    // proxy [kg m^2]

// The five-second script and the passivity observer are the physics case's
// (validation/physics/passivity).
using validation::five_second_script;

TEST(CouplingPassivity, StableGainsInjectNoEnergyOverAFiveSecondScript) {
  const SpringDamperGains gains{1000.0, 10.0, 10.0, 0.1};  // the defaults
  const HapticsConfig config = five_second_script(gains);
  EXPECT_THAT(coupling_stability_warnings(config, "proxy", proxy_model(kMass, kInertia), kSceneDt),
              ::testing::IsEmpty());

  const validation::PassivityMeasurement m = validation::passivity_over_script(gains);
  ASSERT_EQ(m.ticks, 5001u);
  RecordProperty("max_injected_energy_J", std::to_string(m.max_injected));
  RecordProperty("final_injected_energy_J", std::to_string(m.final_injected));
  EXPECT_LE(m.max_injected, 0.0);  // at every tick, not only at the end
  EXPECT_LE(m.final_injected, 0.0);
  EXPECT_LT(m.final_injected, -0.1);  // it did dissipate: tens of newtons over centimetres
  EXPECT_LT(m.deepest, -0.05);        // the taps reached the floor
  EXPECT_GT(m.peak_force, 10.0);
}

TEST(CouplingPassivity, GainsBeyondTheBoundAreReportedAndInjectEnergy) {
  // Kt h^2 + 2 Bt h = 5e6 * 1e-6 + 0.02 = 5.02 > 4 m = 4 with h = 1 ms (the wrench is held a tick).
  const SpringDamperGains gains{5e6, 10.0, 10.0, 0.1};
  const HapticsConfig config = five_second_script(gains);
  const std::vector<std::string> warnings =
      coupling_stability_warnings(config, "probe", proxy_model(kMass, kInertia), kSceneDt);
  EXPECT_THAT(warnings, ::testing::Contains(::testing::AllOf(::testing::HasSubstr("probe"),
                                                             ::testing::HasSubstr("translational coupling"),
                                                             ::testing::HasSubstr("K h^2 + 2 B h < 4 m"))));

  // Stop at 1 J: a passive coupling never gets above 0, and the growth is exponential.
  const validation::PassivityMeasurement m = validation::passivity_over_script(gains, 1.0);
  RecordProperty("time_to_1J_s", std::to_string(m.end_time));
  EXPECT_GT(m.final_injected, 1.0);
  EXPECT_LT(m.end_time, 1.0);  // within the first second
}

TEST(CouplingStabilityCheck, NamesEachViolatedBound) {
  HapticsConfig config = five_second_script({1000.0, 10.0, 10.0, 0.1});
  // 1 g and 1e-6 kg m^2: 1000 * 1e-6 + 2 * 10 * 1e-3 = 0.021 >= 4 m = 0.004, and 2.1e-4 >= 4e-6.
  const ProxyModel light = proxy_model(0.001, 1e-6);
  const std::vector<std::string> warnings = coupling_stability_warnings(config, "needle", light, kSceneDt);
  EXPECT_THAT(warnings, ::testing::ElementsAre(::testing::HasSubstr("translational coupling"),
                                               ::testing::HasSubstr("rotational coupling")));
  // Device side: a 10 g handle under the same coupling and hand (K 1400 N/m, B 32 N s/m).
  config.device.mass = 0.01;
  config.device.inertia = 1e-6;
  EXPECT_THAT(coupling_stability_warnings(config, "probe", proxy_model(kMass, kInertia), kSceneDt),
              ::testing::ElementsAre(::testing::HasSubstr("device handle translational"),
                                     ::testing::HasSubstr("device handle rotational")));
  // dt longer than the haptic period is the proxy's step: 1000 * 0.1^2 = 10 > 4 m.
  EXPECT_THAT(coupling_stability_warnings(config, "probe", proxy_model(kMass, 1.0), 0.1),
              ::testing::Contains(::testing::HasSubstr("h = 0.1 s")));
}

}  // namespace
}  // namespace mssph::test
