// Momentum and energy of a Neo-Hookean body (model neo_hookean), as momentum_test.cpp and
// bar_vibration_test.cpp check them for the paper's model: internal forces sum to zero, a
// spinning deformed body keeps its angular momentum, and a free bar released from a large
// compression keeps its energy.
#include "deformable_fixtures.hpp"
#include "elastic_forces.hpp"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <random>

namespace mssph {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// A free Neo-Hookean box (dx = 1 cm, E = 100 kPa, nu = 0.3) with kernel-gradient correction.
reference::ReferenceBackend neo_hookean_box(const Vector3d& size, double dt) {
  nlohmann::json doc = testing::elastic_scene(0.01, dt);
  nlohmann::json material = testing::elastic_material(1.0e5, 0.3);
  material["model"] = "neo_hookean";
  material["kernel_gradient_correction"] = true;
  doc["bodies"]["box"] = testing::deformable_box(size, Vector3d::Zero(), material);
  return testing::make_backend(doc);
}

// Compressed to det F = 0.55 and sheared, turned, with random particle displacements of 10 % of dx.
void deform_hard(reference::ReferenceBackend& backend) {
  Matrix3d g;
  g << 0.7, 0.2, 0.0, -0.05, 0.85, 0.1, 0.0, 0.0, 0.9;
  testing::deform_body(backend, 0, Eigen::AngleAxisd(0.6, Vector3d(1, -1, 2).normalized()) * g, Vector3d::Zero());
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (Vector3d& x : backend.particles().position) x += 0.001 * Vector3d(unit(random), unit(random), unit(random));
}

// Every pair term enters i's and j's sums with opposite signs: 1e-13 of the summed magnitudes,
// rounding of ~10^4 terms (momentum_test.cpp).
TEST(NeoHookeanMomentum, InternalForcesSumToZero) {
  reference::ReferenceBackend backend = neo_hookean_box({0.06, 0.06, 0.08}, 1e-4);
  deform_hard(backend);
  backend.compute_forces();
  Vector3d sum = Vector3d::Zero();
  double magnitude = 0.0;
  for (const Vector3d& f : backend.deformables().elastic_force) {
    sum += f;
    magnitude += f.norm();
  }
  ASSERT_GT(magnitude, 0.0);
  EXPECT_LT(sum.norm(), 1e-13 * magnitude);
}

// P F^T = mu F F^T + g(J) J I is symmetric, so with correction (sum_j y_ij (x) d_ij = F) particle
// i's forces exert no torque: angular momentum is kept to rounding. 1e-6 per 1000 steps, the
// bound of momentum_test.cpp.
TEST(NeoHookeanMomentum, SpinningDeformedBodyKeepsAngularMomentum) {
  reference::ReferenceBackend backend = neo_hookean_box({0.06, 0.06, 0.08}, 2e-4);
  deform_hard(backend);
  const Vector3d omega(3.0, -5.0, 20.0);
  Vector3d centre = Vector3d::Zero();
  for (const Vector3d& x : backend.particles().position) centre += x;
  centre /= static_cast<double>(backend.particle_count());
  for (std::size_t i = 0; i < backend.particle_count(); ++i) {
    backend.particles().velocity[i] = omega.cross(backend.particles().position[i] - centre);
  }
  const Vector3d l0 = backend.body_states()[0].angular_momentum;
  for (int s = 0; s < 1000; ++s) backend.step();
  EXPECT_LT((backend.body_states()[0].angular_momentum - l0).norm() / l0.norm(), 1e-6);
}

// A free 20 x 4 x 4 bar released from 25 % compression along its axis (det F = 0.75, deep in the
// nonlinear range) vibrates for three of its periods (2 L / c, c = sqrt(E / rho) = 10 m/s:
// 40 ms); leap-frog with conservative forces keeps strain + kinetic energy within 2 % (the bound
// of bar_vibration_test.cpp; its energy oscillates by the O(dt^2) shadow term).
TEST(NeoHookeanEnergy, BarReleasedFromLargeCompressionKeepsItsEnergy) {
  const double dt = 2e-4;  // inside the elastic bound 0.25 h / c_p = 4.3e-4 s
  reference::ReferenceBackend backend = neo_hookean_box({0.2, 0.04, 0.04}, dt);
  testing::deform_body(backend, 0, Vector3d(0.75, 1.0, 1.0).asDiagonal(), Vector3d::Zero());
  const std::vector<double>& mass = backend.setup().mass;
  std::vector<double> energy;
  for (int s = 0; s < 600; ++s) {
    const std::vector<Vector3d> v_before = backend.particles().velocity;
    backend.step();
    double kinetic = 0.0;
    for (std::size_t i = 0; i < mass.size(); ++i) {
      kinetic += 0.5 * mass[i] * (0.5 * (v_before[i] + backend.particles().velocity[i])).squaredNorm();
    }
    energy.push_back(reference::body_strain_energy(backend.setup(), backend.deformables(), 0) + kinetic);
  }
  const auto [lo, hi] = std::minmax_element(energy.begin(), energy.end());
  EXPECT_GT(energy.front(), 0.0);
  EXPECT_LT((*hi - *lo) / energy.front(), 0.02) << "energy from " << *lo << " to " << *hi << " J";
}

}  // namespace
}  // namespace mssph
