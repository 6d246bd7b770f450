// The full_stress viscosity (cpu_reference/fluid_forces.hpp) against the Newtonian stress
// sigma = mu (grad u + grad u^T) (Batchelor, An Introduction to Fluid Dynamics, 1967, sec. 3.3):
// its corrected velocity gradient, and the traction its pair forces carry across a plane, where
// the paper's eq. 3 alone carries mu grad u only.
#include "fluid_forces.hpp"
#include "model/lattice_calibration.hpp"
#include "model/smoothing_kernels.hpp"

#include <gtest/gtest.h>

#include <random>

namespace mssph::reference {
namespace {

constexpr double kSpacing = 0.01;            // dx [m]
constexpr double kSupport = 2.0 * kSpacing;  // h [m], the scenes' default
constexpr double kViscosity = 3.0;           // mu [Pa s]
constexpr double kShearRate = 0.7;           // gamma [1/s]

// Within a jittered lattice the corrected gradient of a linear field u = L x is L itself,
// whatever the particles' volumes (Bonet and Lok 1999).
TEST(FullStressViscosity, VelocityGradientIsExactForLinearFields) {
  Eigen::Matrix3d field;
  field << 0.3, -1.2, 0.5, 2.0, -0.1, 0.7, -0.4, 0.9, 0.25;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.2 * kSpacing, 0.2 * kSpacing);
  std::uniform_real_distribution<double> volume(0.8, 1.2);
  const SpikyGradient grad_w(kSupport);
  const Eigen::Vector3d x_i(jitter(random), jitter(random), jitter(random));
  VelocityGradientSums sums;
  for (int a = -3; a <= 3; ++a) {
    for (int b = -3; b <= 3; ++b) {
      for (int c = -3; c <= 3; ++c) {
        if (a == 0 && b == 0 && c == 0) continue;
        const Eigen::Vector3d x_j =
            kSpacing * Eigen::Vector3d(a, b, c) + Eigen::Vector3d(jitter(random), jitter(random), jitter(random));
        const Eigen::Vector3d u_ji = field * x_j - field * x_i;
        sums.add(volume(random) * kSpacing * kSpacing * kSpacing, u_ji, x_j - x_i, grad_w(x_i - x_j));
      }
    }
  }
  EXPECT_LT((sums.gradient() - field).norm(), 1e-10 * field.norm());
}

// The force per unit area the fluid below the plane y = 0 exerts on the fluid above it, in a rest
// lattice (sites at y = (k + 1/2) dx) moving with u = L x: the pair forces on one column of
// particles above the plane from every particle below it, over the column's area dx^2. The
// full_stress term takes A = L at every particle, which VelocityGradientIsExactForLinearFields
// shows the gradient pass returns there.
Eigen::Vector3d traction_on_upper_fluid(const Eigen::Matrix3d& field, bool full_stress) {
  const SpikyGradient grad_w(kSupport);
  const ViscosityLaplacian lap_w(kSupport);
  const double g = lattice_gradient_consistency(kSpacing, kSupport);
  const double volume = kSpacing * kSpacing * kSpacing;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d x_i(0.0, (k + 0.5) * kSpacing, 0.0);
    for (int a = -3; a <= 3; ++a) {
      for (int m = 0; m < 3; ++m) {
        for (int c = -3; c <= 3; ++c) {
          const Eigen::Vector3d x_j(a * kSpacing, -(m + 0.5) * kSpacing, c * kSpacing);
          const Eigen::Vector3d r_ij = x_i - x_j;
          if (r_ij.norm() >= kSupport) continue;
          force += viscosity_force_pair(kViscosity, volume, volume, lap_w(r_ij.norm()), field * x_i, field * x_j);
          if (full_stress) {
            force += transposed_stress_force_pair(kViscosity, volume, field, volume, field, g, grad_w(r_ij));
          }
        }
      }
    }
  }
  return force / (kSpacing * kSpacing);
}

// Both shear flows u = (gamma y, 0, 0) and u = (0, gamma x, 0) have the shear stress
// sigma_xy = mu gamma, so the upper fluid feels -mu gamma e_x from below. The full_stress
// viscosity carries it for both (2 %: the lattice sums of eq. 3's Laplacian at h = 2 dx are 0.99
// of the continuum's); eq. 3 alone carries mu du_x/dy only and misses the second entirely.
TEST(FullStressViscosity, APlaneCarriesTheNewtonianShearStress) {
  Eigen::Matrix3d along_x = Eigen::Matrix3d::Zero();
  along_x(0, 1) = kShearRate;  // u_x = gamma y
  Eigen::Matrix3d along_y = Eigen::Matrix3d::Zero();
  along_y(1, 0) = kShearRate;  // u_y = gamma x
  const Eigen::Vector3d expected(-kViscosity * kShearRate, 0.0, 0.0);
  for (const Eigen::Matrix3d& field : {along_x, along_y}) {
    EXPECT_LT((traction_on_upper_fluid(field, true) - expected).norm(), 0.02 * expected.norm()) << field;
  }
  EXPECT_LT((traction_on_upper_fluid(along_x, false) - expected).norm(), 0.02 * expected.norm());
  EXPECT_GT((traction_on_upper_fluid(along_y, false) - expected).norm(), 0.9 * expected.norm());
}

}  // namespace
}  // namespace mssph::reference
