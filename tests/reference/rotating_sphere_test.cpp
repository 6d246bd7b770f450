// The turning-sphere case (validation/physics/rotating_sphere) on the cpu backend at a coarse
// spacing: the fluid's torque on a sphere turning in the case's concentric container is
// Kirchhoff's with the container's factor, within a coarse tolerance; a free-slip sphere (the
// planted error: its material's viscosity zero, so the interface viscosity of paper eq. 7 is
// zero and nothing turns the fluid) falls far outside the case's own tolerance.
#include "physics/rotating_sphere/rotating_sphere.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mssph::testing {
namespace {

// R = 4 dx at h = 2 dx, 10 Pa s, 1 rad/s, run for 6 R^2 / nu, a fifth of the case's run (for the
// suite's time): the torque has then risen to within 8 % of where it settles.
double torque_over_kirchhoff(double sphere_viscosity_factor) {
  Scene scene = validation::rotating_sphere_scene(validation::kRotatingSphereRadius / 4.0, 2.0, 10.0, 1.0);
  scene.simulation.duration /= 5.0;
  for (BodyConfig& body : scene.bodies) {
    if (body.name == "sphere") body.material.viscosity *= sphere_viscosity_factor;
  }
  const validation::RotatingSphereMeasurement m = validation::measure_rotating_sphere("cpu", scene, 1.0);
  return m.torque / m.expected_torque;
}

// The case's tolerance at its coarser spacings.
constexpr double kCaseTolerance = 0.20;

TEST(RotatingSphere, FreeSlipSphereFailsTheCheck) {
  // Measured 0.78 here; the full run at 4 dx settles at 0.73 on cuda (decision 065), the case's
  // coarsest run (6 dx) at 0.90. The bound is for this spacing, not the case's.
  EXPECT_NEAR(torque_over_kirchhoff(1.0), 1.0, 0.30);
  // Measured 0.10.
  EXPECT_GT(std::abs(torque_over_kirchhoff(0.0) - 1.0), kCaseTolerance);
}

}  // namespace
}  // namespace mssph::testing
