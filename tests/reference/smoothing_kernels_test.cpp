// The smoothing kernels (Mueller et al. 2003) against their defining properties.
#include "model/lattice_calibration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace mssph::reference {
namespace {

constexpr double kH = 0.04;

// Midpoint rule for int_0^h 4 pi r^2 f(r) dr; 20000 intervals make the quadrature error
// negligible (< 1e-8) against the tolerances below.
template <class F>
double radial_integral(F f, double h) {
  const int n = 20000;
  const double dr = h / n;
  double sum = 0.0;
  for (int k = 0; k < n; ++k) {
    const double r = (k + 0.5) * dr;
    sum += 4.0 * std::numbers::pi * r * r * f(r) * dr;
  }
  return sum;
}

TEST(SphKernels, Poly6IntegratesToOne) {
  const Poly6Kernel w(kH);
  EXPECT_NEAR(radial_integral([&](double r) { return w(r * r); }, kH), 1.0, 1e-6);
}

TEST(SphKernels, Poly6VanishesAtAndBeyondSupport) {
  const Poly6Kernel w(kH);
  EXPECT_EQ(w(kH * kH), 0.0);
  EXPECT_EQ(w(4.0 * kH * kH), 0.0);
  EXPECT_GT(w(0.99 * kH * 0.99 * kH), 0.0);
}

// The spiky gradient is the gradient of W = 15 / (pi h^6) (h - r)^3, itself normalised to 1.
TEST(SphKernels, SpikyGradientIsTheGradientOfTheNormalisedSpikyKernel) {
  const auto spiky = [](double r) {
    return r >= kH ? 0.0 : 15.0 / (std::numbers::pi * std::pow(kH, 6)) * std::pow(kH - r, 3);
  };
  EXPECT_NEAR(radial_integral(spiky, kH), 1.0, 1e-6);
  const SpikyGradient grad_w(kH);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-kH, kH);
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::Vector3d r(u(random), u(random), u(random));
    if (r.norm() >= 0.98 * kH || r.norm() < 0.02 * kH) continue;
    const double step = 1e-7;
    Eigen::Vector3d numeric;
    for (int a = 0; a < 3; ++a) {
      const Eigen::Vector3d e = Eigen::Vector3d::Unit(a) * step;
      numeric[a] = (spiky((r + e).norm()) - spiky((r - e).norm())) / (2.0 * step);
    }
    // Central differences with step 1e-7 m on a cubic: relative error ~1e-7.
    EXPECT_LT((grad_w(r) - numeric).norm(), 1e-5 * numeric.norm()) << "r = " << r.transpose();
  }
}

TEST(SphKernels, SpikyGradientIsOddAndPointsInward) {
  const SpikyGradient grad_w(kH);
  const Eigen::Vector3d r(0.01, -0.005, 0.02);
  EXPECT_TRUE((grad_w(-r) + grad_w(r)).isZero(0.0));
  EXPECT_LT(grad_w(r).dot(r), 0.0);  // W decreases outward
  EXPECT_TRUE(grad_w(Eigen::Vector3d::Zero()).isZero(0.0));
  EXPECT_TRUE(grad_w(Eigen::Vector3d(kH, 0.0, 0.0)).isZero(0.0));
}

// The Laplacian of a normalised radial kernel satisfies int r^2 lap W dV = int lap(r^2) W dV = 6.
TEST(SphKernels, ViscosityLaplacianIsTheLaplacianOfANormalisedKernel) {
  const ViscosityLaplacian lap_w(kH);
  EXPECT_NEAR(radial_integral([&](double r) { return r * r * lap_w(r); }, kH), 6.0, 1e-5);
  EXPECT_EQ(lap_w(kH), 0.0);
}

TEST(SphKernels, SpikyKernelIsNormalisedAndItsGradientIsItsDerivative) {
  const SpikyKernel w(kH);
  EXPECT_NEAR(radial_integral([&](double r) { return w(r); }, kH), 1.0, 1e-6);
  const SpikyGradient grad_w(kH);
  const Eigen::Vector3d r(0.011, -0.007, 0.015);
  const double step = 1e-7;
  // Central difference of W along r against the gradient's radial component; relative error
  // of the difference quotient ~1e-7.
  const double numeric = (w(r.norm() + step) - w(r.norm() - step)) / (2.0 * step);
  EXPECT_NEAR(grad_w(r).dot(r.normalized()), numeric, 1e-5 * std::abs(numeric));
}

// Lattice sums approach the continuum integrals as the kernel covers more neighbours:
// sum_j W_ij dx^3 -> int W = 1 and dx^3 sum_j x_ji (x) grad W_ij -> I. The simulation calibrates
// with exactly these sums, so they must be the right quantities: at h = 2 dx the spiky kernel's
// peak puts ~half the number density on the particle itself (sum 1.24), while the gradient sum is
// already within 5% of I.
TEST(SphKernels, LatticeSumsConvergeToTheirIntegrals) {
  const double dx = 0.02;
  double previous_density_error = 1e9;
  double previous_gradient_error = 1e9;
  for (const double ratio : {2.0, 3.0, 4.0}) {
    const double density_error = std::abs(lattice_number_density(dx, ratio * dx) * dx * dx * dx - 1.0);
    const double gradient_error = std::abs(lattice_gradient_consistency(dx, ratio * dx) - 1.0);
    EXPECT_LT(density_error, previous_density_error) << "h = " << ratio << " dx";
    EXPECT_LT(gradient_error, previous_gradient_error) << "h = " << ratio << " dx";
    previous_density_error = density_error;
    previous_gradient_error = gradient_error;
  }
  EXPECT_LT(previous_density_error, 0.05);  // h = 4 dx
  EXPECT_NEAR(lattice_gradient_consistency(dx, 2.0 * dx), 1.0, 0.05);
}

}  // namespace
}  // namespace mssph::reference
