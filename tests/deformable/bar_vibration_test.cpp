// Dynamics of a free elastic bar: released from a uniform 1 % stretch it vibrates at its first
// longitudinal frequency f = (1 / 2L) sqrt(E / rho) and, without damping, keeps its energy; with
// mass-proportional damping at rate gamma its vibration energy decays as exp(-gamma t).
//
// Resolution: dx = 1 cm, h = 2 dx, a 30 x 6 x 6 particle bar (L = 0.3 m, slender enough that the
// lateral-inertia correction (pi nu r_g / L)^2 is 0.6 %), kernel-gradient correction on. Without
// correction the scheme is not conservative (its forces leave out how the rotations R_i depend on
// the positions, a term that vanishes only where sum_j y_ij (x) d_ij = F, i.e. with correction):
// this bar's energy then grows by 54 % in 10 periods (period 0.955 T), so these tests run with
// correction on.
#include "physics/bar_vibration/bar_vibration.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mssph {
namespace {

// The bar (validation/physics/bar_vibration/scene.json) and the measurements are the physics
// case's.
using validation::BarHistory;
using validation::measured_period;
using validation::stretched_bar;

// 10 % (the brief's bound) on the frequency: the particles' Shepard volumes V0_i at the surface
// exceed their share of the bar's volume (its strain energy at the start is 12 % above
// 1/2 E e^2 V), which stiffens this bar; measured period 0.932 T. 2 % on the energy over 10
// periods (the brief's bound); measured drift 0.5 %.
TEST(BarVibration, FreeBarOscillatesAtItsLongitudinalFrequencyAndKeepsItsEnergy) {
  reference::ReferenceBackend backend = stretched_bar(0.0);
  const double period = validation::bar_period(backend);
  const BarHistory history = validation::run_bar(backend, 10.0 * period);
  EXPECT_NEAR(measured_period(history) / period, 1.0, 0.10);
  EXPECT_LT(validation::energy_drift(history), 0.02);
}

// Mass-proportional damping at gamma = 5 /s: energy decays as exp(-gamma t). The decay rate is a
// least-squares fit of log(energy) over 4 whole periods (the energy ripples at twice the
// vibration frequency as it moves between strain and motion; whole periods average that out).
// 5 %: the fit over a rippled decay at gamma / omega = 0.05, and the explicit damping's first-order
// error gamma dt / 2 = 0.08 %.
TEST(BarVibration, DampingDecaysTheVibrationAtTheConfiguredRate) {
  const double gamma = 5.0;
  reference::ReferenceBackend backend = stretched_bar(gamma);
  const double period = validation::bar_period(backend);
  const BarHistory history = validation::run_bar(backend, 4.0 * period);
  const double slope = validation::energy_decay_rate(history);
  EXPECT_NEAR(-slope / gamma, 1.0, 0.05);
}

}  // namespace
}  // namespace mssph
