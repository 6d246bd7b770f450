// A cantilever sagging under its own weight: the static tip deflection against Euler-Bernoulli
// beam theory, w(x) = q x^2 (6 L^2 - 4 L x + x^2) / (24 E I), w(L) = q L^4 / (8 E I), with
// q = rho g A the weight per length and I = H^4 / 12 for a square section of side H.
//
// Resolution: dx = 1 cm, h = 2 dx; beam L = 0.24 m (24 particles), H = 0.04 m (4 x 4 particles),
// clamped by three fixed layers behind x = 0. Slenderness L / H = 6: Timoshenko's shear
// deflection adds 2.9 % to Euler-Bernoulli's. E = 3 MPa keeps the sag at 4 % of L, where the
// geometric nonlinearity of the beam is below 0.5 %.
#include "physics/cantilever/cantilever.hpp"

#include <gtest/gtest.h>

namespace mssph {
namespace {

constexpr double kDx = 0.01;

// The scene (validation/physics/cantilever/scene.json) and the measurement are the physics
// case's: tip deflection (mean over the last layer of particles) once the beam has come to rest.
double static_tip_deflection(bool correction) {
  const validation::CantileverMeasurement m = validation::measure_cantilever("reference", kDx, correction);
  EXPECT_EQ(m.fixed_particles, 3u * 4u * 4u);
  return m.tip / m.euler_bernoulli;
}

// 15 % (the brief's bound): 4 particles across the section resolve the bending stress only
// coarsely, and Timoshenko shear adds 2.9 %. Measured: 1.02 times Euler-Bernoulli with the
// default (uncorrected) gradient, 1.07 with kernel-gradient correction.
TEST(Cantilever, TipDeflectionUnderGravityFollowsEulerBernoulli) {
  for (bool correction : {false, true}) {
    EXPECT_NEAR(static_tip_deflection(correction), 1.0, 0.15) << "correction " << correction;
  }
}

}  // namespace
}  // namespace mssph
