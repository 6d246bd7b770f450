#pragma once
// Smoothing kernels of Mueller, Charypar and Gross 2003 ("Particle-based fluid simulation for
// interactive applications"), double precision, support radius h: W = 0 for r >= h.
// Each kernel is one small class with its constants computed once.
#include <Eigen/Core>

#include <cmath>
#include <numbers>

namespace mssph::reference {

// poly6: W(r) = 315 / (64 pi h^9) (h^2 - r^2)^3, used for densities (paper eq. 1).
class Poly6Kernel {
 public:
  explicit Poly6Kernel(double h) : h2_(h * h), coefficient_(315.0 / (64.0 * std::numbers::pi * std::pow(h, 9))) {}
  double operator()(double r2) const {  // takes r^2: no square root on the hot path
    if (r2 >= h2_) return 0.0;
    const double d = h2_ - r2;
    return coefficient_ * d * d * d;
  }

 private:
  double h2_;
  double coefficient_;
};

// Spiky gradient: grad W(r_vec) = -45 / (pi h^6) (h - r)^2 r_vec / r, used for pressure and
// elasticity. grad W is taken with respect to the first particle: r_vec = x_i - x_j. At r = 0
// the direction is undefined and the gradient is taken as zero (coincident particles exert no
// directional force).
class SpikyGradient {
 public:
  explicit SpikyGradient(double h) : h_(h), coefficient_(-45.0 / (std::numbers::pi * std::pow(h, 6))) {}
  Eigen::Vector3d operator()(const Eigen::Vector3d& r_vec) const {
    const double r = r_vec.norm();
    if (r >= h_ || r <= 1e-12 * h_) return Eigen::Vector3d::Zero();
    const double d = h_ - r;
    return (coefficient_ * d * d / r) * r_vec;
  }

 private:
  double h_;
  double coefficient_;
};

// Viscosity kernel Laplacian: lap W(r) = 45 / (pi h^6) (h - r), used by paper eq. 3.
class ViscosityLaplacian {
 public:
  explicit ViscosityLaplacian(double h) : h_(h), coefficient_(45.0 / (std::numbers::pi * std::pow(h, 6))) {}
  double operator()(double r) const { return r >= h_ ? 0.0 : coefficient_ * (h_ - r); }

 private:
  double h_;
  double coefficient_;
};

// Number density sum_j W(x_i - x_j) at a particle inside an infinite cubic lattice of spacing dx,
// self included. Particle masses are calibrated with it so that a rest lattice has exactly the
// rest density (rho = m delta with m = rho0 / delta0).
inline double lattice_number_density(double dx, double h) {
  const Poly6Kernel w(h);
  const int n = static_cast<int>(std::ceil(h / dx));
  double sum = 0.0;
  for (int i = -n; i <= n; ++i) {
    for (int j = -n; j <= n; ++j) {
      for (int k = -n; k <= n; ++k) sum += w(dx * dx * static_cast<double>(i * i + j * j + k * k));
    }
  }
  return sum;
}

// The kernel-gradient consistency of a rest lattice: c with sum_j V_j (x_j - x_i) (x) grad W(x_i - x_j)
// = c I at a particle inside an infinite cubic lattice (V_j = 1 / delta0). A consistent SPH
// gradient has c = 1; at h = 2 dx the spiky kernel gives c = 0.947, so pressure gradients would
// come out 5.3% weak. The pressure force divides by c, as the particle masses divide by delta0:
// both calibrate the discrete sums on the rest lattice.
inline double lattice_gradient_consistency(double dx, double h) {
  const SpikyGradient grad_w(h);
  const double volume = 1.0 / lattice_number_density(dx, h);
  const int n = static_cast<int>(std::ceil(h / dx));
  double sum = 0.0;
  for (int i = -n; i <= n; ++i) {
    for (int j = -n; j <= n; ++j) {
      for (int k = -n; k <= n; ++k) {
        const Eigen::Vector3d x_ji(dx * i, dx * j, dx * k);  // x_j - x_i
        sum += volume * x_ji.x() * grad_w(-x_ji).x();
      }
    }
  }
  return sum;
}

}  // namespace mssph::reference
