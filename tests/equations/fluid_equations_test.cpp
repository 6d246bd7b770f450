// Paper eq. 1-3 and 7, the equation of state and the full_stress viscosity, float32 (kernels/common/fluid_physics.hpp)
// against the float64 twins of the same names (cpu_reference/density.hpp, fluid_forces.hpp). Method and tolerance:
// twin_support.hpp. Inputs span the scenes' ranges: spacings 1-5 cm, rest densities 500-3000 kg/m^3, stiffnesses up to
// 1e4 m^2/s^2, viscosities up to 10 Pa s.
#include "common/fluid_physics.hpp"
#include "density.hpp"
#include "fluid_forces.hpp"
#include "model/smoothing_kernels.hpp"
#include "twin_support.hpp"

#include <numbers>

namespace mssph::testing {
namespace {

// A lattice spacing dx and the number density delta0 = 1.236 / dx^3 of a rest lattice at h = 2 dx.
struct Lattice {
  double dx;
  double rest_number_density;

  // A particle volume of 0.5 to 1.5 cells dx^3, rounded to float32.
  double draw_volume(TwinDraws& draws) const { return TwinDraws::rounded(draws.uniform(0.5, 1.5) * dx * dx * dx); }
};
Lattice draw_lattice(TwinDraws& draws) {
  const double dx = draws.uniform(0.01, 0.05);
  return {dx, 1.236 / (dx * dx * dx)};
}

TEST(FluidEquationTwins, DensityFromNumberDensity) {
  TwinDraws draws("FluidEquationTwins.DensityFromNumberDensity");
  TwinComparison rho("density (eq. 1)");
  for (int k = 0; k < kDraws; ++k) {
    const Lattice lattice = draw_lattice(draws);
    const double rest_density = draws.uniform(500.0, 3000.0);
    const double number_density = TwinDraws::rounded(draws.uniform(0.3, 2.0) * lattice.rest_number_density);
    // The float code reads 1 / delta0, rounded once (kernels::StepParameters).
    const float inverse = static_cast<float>(1.0 / lattice.rest_number_density);
    const double expected = reference::density(rest_density, number_density, lattice.rest_number_density);
    rho.add(kernels::density(static_cast<float>(rest_density), static_cast<float>(number_density), inverse), expected,
            expected);
  }
}

TEST(FluidEquationTwins, EquationOfState) {
  TwinDraws draws("FluidEquationTwins.EquationOfState");
  TwinComparison pressure("equation of state", 0.5);  // a third of the draws are clamped to 0
  int clamped = 0;
  for (int k = 0; k < kDraws; ++k) {
    const double stiffness = draws.uniform(10.0, 1e4);
    const double rest_density = draws.uniform(500.0, 3000.0);
    const double rho = TwinDraws::rounded(draws.uniform(0.95, 1.1) * rest_density);
    const double expected = reference::equation_of_state(stiffness, rho, rest_density);
    const float got = kernels::equation_of_state(static_cast<float>(stiffness), static_cast<float>(rho),
                                                 static_cast<float>(rest_density));
    if (rho < rest_density) {
      ++clamped;
      EXPECT_EQ(got, 0.0f) << "draw " << k << ": below rest density the pressure is clamped to 0";
    }
    // rho - rho0 is exact in float32 (Sterbenz), so the product's rounding is relative to P.
    pressure.add(got, expected, stiffness * std::abs(rho - rest_density));
  }
  EXPECT_GT(clamped, kDraws / 5);
}

TEST(FluidEquationTwins, PressureForcePair) {
  TwinDraws draws("FluidEquationTwins.PressureForcePair");
  TwinComparison force("pressure force pair (eq. 2)");
  for (int k = 0; k < kDraws; ++k) {
    const Lattice lattice = draw_lattice(draws);
    const double volume_i = lattice.draw_volume(draws);
    const double volume_j = lattice.draw_volume(draws);
    const double pressure_i = draws.uniform(0.0, 1e4), pressure_j = draws.uniform(0.0, 1e4);
    const double consistency = draws.uniform(0.9, 1.0);
    const double h = 2.0 * lattice.dx;
    const Eigen::Vector3d grad_w = draws.vector(45.0 / (std::numbers::pi * std::pow(h, 4)));
    const Eigen::Vector3d expected =
        reference::pressure_force_pair(volume_i, pressure_i, volume_j, pressure_j, consistency, grad_w);
    const kernels::Vec3 got = kernels::pressure_force_pair(
        {static_cast<float>(volume_i), static_cast<float>(pressure_i)},
        {static_cast<float>(volume_j), static_cast<float>(pressure_j)},
        static_cast<float>(1.0 / consistency),  // 1 / g rounded once, as kernels::StepParameters holds it
        to_float(grad_w));
    // Both pressure terms are >= 0: no cancellation, the scale is the force itself.
    force.add(to_double(got), expected, expected.norm());
  }
}

TEST(FluidEquationTwins, ViscosityForcePair) {
  TwinDraws draws("FluidEquationTwins.ViscosityForcePair");
  TwinComparison force("viscosity force pair (eq. 3)");
  for (int k = 0; k < kDraws; ++k) {
    const Lattice lattice = draw_lattice(draws);
    const double h = 2.0 * lattice.dx;
    const double mu = draws.uniform(1e-3, 10.0);
    const double volume_i = lattice.draw_volume(draws);
    const double volume_j = lattice.draw_volume(draws);
    const double laplacian = TwinDraws::rounded(draws.uniform(0.0, 1.0) * 45.0 / (std::numbers::pi * std::pow(h, 5)));
    const Eigen::Vector3d velocity_i = draws.vector(1.0), velocity_j = draws.vector(1.0);
    const Eigen::Vector3d expected =
        reference::viscosity_force_pair(mu, volume_i, volume_j, laplacian, velocity_i, velocity_j);
    const kernels::Vec3 got = kernels::viscosity_force_pair(static_cast<float>(mu), static_cast<float>(volume_i),
                                                            static_cast<float>(volume_j), static_cast<float>(laplacian),
                                                            to_float(velocity_i), to_float(velocity_j));
    // v_j - v_i may cancel: the scale holds both velocities.
    force.add(to_double(got), expected, mu * volume_i * volume_j * laplacian * (velocity_i.norm() + velocity_j.norm()));
  }
}

TEST(FluidEquationTwins, InterfaceViscosity) {
  TwinDraws draws("FluidEquationTwins.InterfaceViscosity");
  TwinComparison mu("interface viscosity (eq. 3 between bodies)");
  for (int k = 0; k < kDraws; ++k) {
    const double mu_i = draws.uniform(1e-3, 10.0), mu_j = draws.uniform(1e-3, 10.0);
    const double expected = reference::interface_viscosity(mu_i, mu_j);
    mu.add(kernels::interface_viscosity(static_cast<float>(mu_i), static_cast<float>(mu_j)), expected, expected);
  }
  // A body of zero viscosity (a free-slip wall) exerts no friction in both.
  EXPECT_EQ(reference::interface_viscosity(0.0, 3.0), 0.0);
  EXPECT_EQ(kernels::interface_viscosity(0.0f, 3.0f), 0.0f);
  EXPECT_EQ(kernels::interface_viscosity(0.0f, 0.0f), 0.0f);
}

TEST(FluidEquationTwins, InteractionForce) {
  TwinDraws draws("FluidEquationTwins.InteractionForce");
  TwinComparison force("interaction force (eq. 7)", 0.8);  // the two parts may nearly cancel
  for (int k = 0; k < kDraws; ++k) {
    const Eigen::Vector3d pressure = draws.vector(1.0), viscosity = draws.vector(0.5);
    force.add(to_double(kernels::interaction_force(to_float(pressure), to_float(viscosity))),
              reference::interaction_force(pressure, viscosity), pressure.norm() + viscosity.norm());
  }
}

// The full_stress viscosity's velocity gradient from one neighbourhood: the 26 sites around a
// particle at h = 2 dx, jittered by 0.2 dx, with random velocities and the spiky gradient; A = G M^-1
// of both precisions from the same rounded inputs.
TEST(FluidEquationTwins, VelocityGradient) {
  TwinDraws draws("FluidEquationTwins.VelocityGradient");
  TwinComparison gradient("velocity gradient A = G M^-1 (full_stress)");
  for (int k = 0; k < kDraws; ++k) {
    const Lattice lattice = draw_lattice(draws);
    const double dx = lattice.dx;
    const double cell = dx * dx * dx;
    reference::VelocityGradientSums expected;
    kernels::VelocityGradientSums got = kernels::zero_velocity_gradient_sums();
    double velocity_scale = 0.0;
    for (int a = -1; a <= 1; ++a) {
      for (int b = -1; b <= 1; ++b) {
        for (int c = -1; c <= 1; ++c) {
          if (a == 0 && b == 0 && c == 0) continue;
          const double volume = TwinDraws::rounded(draws.uniform(0.8, 1.2) * cell);
          const Eigen::Vector3d x_ji = to_double(
              to_float(Eigen::Vector3d(dx * (a + draws.uniform(-0.2, 0.2)), dx * (b + draws.uniform(-0.2, 0.2)),
                                       dx * (c + draws.uniform(-0.2, 0.2)))));
          const Eigen::Vector3d u_ji = draws.vector(1.0);
          const Eigen::Vector3d grad_w = to_double(to_float(SpikyGradient(2.0 * dx)(-x_ji)));
          expected.add(volume, u_ji, x_ji, grad_w);
          got.add(static_cast<float>(volume), to_float(u_ji), to_float(x_ji), to_float(grad_w));
          velocity_scale = std::max(velocity_scale, u_ji.norm());
        }
      }
    }
    // G sums velocity differences that may cancel: the scale is the largest difference over dx.
    gradient.add(to_double(got.gradient()), expected.gradient(), velocity_scale / dx);
  }
}

TEST(FluidEquationTwins, TransposedStressForcePair) {
  TwinDraws draws("FluidEquationTwins.TransposedStressForcePair");
  TwinComparison force("transposed stress force pair (full_stress)");
  for (int k = 0; k < kDraws; ++k) {
    const Lattice lattice = draw_lattice(draws);
    const double mu = draws.uniform(1e-3, 10.0);
    const double volume_i = lattice.draw_volume(draws);
    const double volume_j = lattice.draw_volume(draws);
    const Eigen::Matrix3d gradient_i = draws.matrix(10.0), gradient_j = draws.matrix(10.0);
    const double consistency = draws.uniform(0.9, 1.0);
    const Eigen::Vector3d grad_w = draws.vector(45.0 / (std::numbers::pi * std::pow(2.0 * lattice.dx, 4)));
    const Eigen::Vector3d expected =
        reference::transposed_stress_force_pair(mu, volume_i, gradient_i, volume_j, gradient_j, consistency, grad_w);
    const kernels::Vec3 got = kernels::transposed_stress_force_pair(
        static_cast<float>(mu), static_cast<float>(volume_i), to_float(gradient_i), static_cast<float>(volume_j),
        to_float(gradient_j), static_cast<float>(1.0 / consistency), to_float(grad_w));
    // The two particles' stresses may cancel: the scale holds both.
    const double scale = mu / consistency * grad_w.norm() *
                         (volume_i * volume_i * gradient_i.norm() + volume_j * volume_j * gradient_j.norm());
    force.add(to_double(got), expected, scale);
  }
}

}  // namespace
}  // namespace mssph::testing
