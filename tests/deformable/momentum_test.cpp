// Conservation of momentum by the internal forces of a deformable body (paper eq. 6 with the
// optional viscous stress, the zero-energy control and damping): their sum vanishes, and a free, spinning, deformed
// body keeps its angular momentum.
#include "deformable_fixtures.hpp"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <random>

namespace mssph {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

const Vector3d kCentre(0.0, 0.0, 0.2);

// A free 6 x 6 x 8 block (dx = 1 cm) with the given extra material keys.
reference::ReferenceBackend free_block(const nlohmann::json& extra, double dt) {
  nlohmann::json doc = testing::elastic_scene(0.01, dt);
  nlohmann::json material = testing::elastic_material(1.0e5, 0.3);
  material.update(extra);
  doc["bodies"]["block"] = testing::deformable_box({0.06, 0.06, 0.08}, kCentre, material);
  return testing::make_backend(doc);
}

// A deformation far from a rotation: stretch, shear and a rigid turn, plus random particle
// displacements of 10 % of dx so that no symmetry helps the sums cancel.
void deform_irregularly(reference::ReferenceBackend& backend) {
  Matrix3d g;
  g << 1.03, 0.02, 0.0, -0.01, 0.98, 0.015, 0.005, 0.0, 1.01;
  testing::deform_body(backend, 0, Eigen::AngleAxisd(0.6, Vector3d(1, -1, 2).normalized()) * g, kCentre);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (Vector3d& x : backend.particles().position) x += 0.001 * Vector3d(unit(random), unit(random), unit(random));
}

// The elastic, hourglass and damping forces each sum to zero over the body: every pair term
// enters i's and j's sums with opposite signs. 1e-13 of the summed magnitudes: a sum of ~10^4
// terms rounded at 1e-16 each.
TEST(Momentum, InternalForcesSumToZero) {
  for (bool correction : {false, true}) {
    nlohmann::json extra = {
        {"kernel_gradient_correction", correction}, {"zero_energy_stiffness", 5.0}, {"damping", 20.0}};
    if (correction) extra["viscous_modulus"] = 5.0;  // its stress acts through eq. 6's pair terms
    reference::ReferenceBackend backend = free_block(extra, 1e-4);
    deform_irregularly(backend);
    for (Vector3d& v : backend.particles().velocity) v = Vector3d(0.1, -0.2, 0.05) + 0.3 * v.Random();
    backend.compute_forces();
    const reference::DeformableState& state = backend.deformables();
    for (const auto* forces : {&state.elastic_force, &state.hourglass_force, &state.damping_force}) {
      Vector3d sum = Vector3d::Zero();
      double magnitude = 0.0;
      for (const Vector3d& f : *forces) {
        sum += f;
        magnitude += f.norm();
      }
      ASSERT_GT(magnitude, 0.0);
      EXPECT_LT(sum.norm(), 1e-13 * magnitude) << "correction " << correction;
    }
  }
}

// Spins a deformed free block at 20 rad/s for 1000 steps and returns |L_end - L_0| / |L_0|.
// Leap-frog conserves sum_i m_i x_n x v_{n-1/2} exactly when the internal forces exert no net
// torque, and with zero linear momentum that is the angular momentum body_states() reports.
double angular_momentum_drift(const nlohmann::json& extra) {
  reference::ReferenceBackend backend = free_block(extra, 2e-4);
  deform_irregularly(backend);
  const Vector3d omega(3.0, -5.0, 20.0);
  const BodySetup& body = backend.setup().bodies[0];
  Vector3d centre = Vector3d::Zero();
  for (std::size_t i = body.first; i < body.first + body.count; ++i) centre += backend.particles().position[i];
  centre /= static_cast<double>(body.count);
  for (std::size_t i = body.first; i < body.first + body.count; ++i) {
    backend.particles().velocity[i] = omega.cross(backend.particles().position[i] - centre);
  }
  const Vector3d l0 = backend.body_states()[0].angular_momentum;
  for (int s = 0; s < 1000; ++s) backend.step();
  return (backend.body_states()[0].angular_momentum - l0).norm() / l0.norm();
}

// With kernel-gradient correction, sum_j y_ij (x) d_ij = F at every particle, so the torque of
// particle i's forces, the skew part of P_i F_i^T = F_i S_i F_i^T, vanishes: angular momentum is
// conserved to rounding. 1e-6 per 1000 steps is the brief's bound; rounding gives ~1e-13.
TEST(Momentum, SpinningDeformedBodyKeepsAngularMomentumWithCorrection) {
  EXPECT_LT(angular_momentum_drift({{"kernel_gradient_correction", true}}), 1e-6);
  EXPECT_LT(
      angular_momentum_drift({{"kernel_gradient_correction", true}, {"zero_energy_stiffness", 5.0}, {"damping", 20.0}}),
      1e-6);
  EXPECT_LT(angular_momentum_drift({{"kernel_gradient_correction", true}, {"viscous_modulus", 5.0}}), 1e-6);
}

}  // namespace
}  // namespace mssph
