// The smoothing kernels (Mueller et al. 2003) against their defining properties.
#include "sph_kernels.hpp"

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
  const auto spiky = [](double r) { return r >= kH ? 0.0 : 15.0 / (std::numbers::pi * std::pow(kH, 6)) * std::pow(kH - r, 3); };
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

// Lattice sums approximate the continuum integrals: sum_j W_ij dx^3 ~ int W = 1, and the
// discrete gradient of a linear field ~ its gradient. At h = 2 dx both are within a few percent;
// the calibration constants used by the simulation are exactly these sums.
TEST(SphKernels, LatticeSumsApproximateTheirIntegrals) {
  const double dx = 0.02;
  EXPECT_NEAR(lattice_number_density(dx, 2.0 * dx) * dx * dx * dx, 1.0, 0.02);
  EXPECT_NEAR(lattice_gradient_consistency(dx, 2.0 * dx), 1.0, 0.06);
  // Finer kernels (more neighbours) converge: h = 3 dx is closer to 1 than h = 2 dx.
  EXPECT_LT(std::abs(lattice_gradient_consistency(dx, 3.0 * dx) - 1.0),
            std::abs(lattice_gradient_consistency(dx, 2.0 * dx) - 1.0));
}

}  // namespace
}  // namespace mssph::reference
