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

// Spiky kernel (Desbrun and Gascuel 1996): W(r) = 15 / (pi h^6) (h - r)^3, used for the number
// densities behind pressure, so that the pressure force is the gradient of the same kernel.
class SpikyKernel {
 public:
  explicit SpikyKernel(double h) : h_(h), coefficient_(15.0 / (std::numbers::pi * std::pow(h, 6))) {}
  double operator()(double r) const {
    if (r >= h_) return 0.0;
    const double d = h_ - r;
    return coefficient_ * d * d * d;
  }

 private:
  double h_;
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

// Sums over the neighbours of a particle inside an infinite cubic lattice of spacing dx. The
// simulation calibrates its discrete sums with them, so that a rest lattice is exactly at rest
// density and feels exactly the gradient of a linear pressure field.
template <class Visit>
void for_each_lattice_neighbour(double dx, double h, Visit&& visit) {
  const int n = static_cast<int>(std::ceil(h / dx));
  for (int i = -n; i <= n; ++i) {
    for (int j = -n; j <= n; ++j) {
      for (int k = -n; k <= n; ++k) visit(Eigen::Vector3d(dx * i, dx * j, dx * k));  // x_j - x_i
    }
  }
}

// delta0 = sum_j W_spiky(|x_i - x_j|), self included (1.236 / dx^3 at h = 2 dx: the spiky
// kernel's peak puts almost half of it on the particle itself).
inline double lattice_number_density(double dx, double h) {
  const SpikyKernel w(h);
  double sum = 0.0;
  for_each_lattice_neighbour(dx, h, [&](const Eigen::Vector3d& x_ji) { sum += w(x_ji.norm()); });
  return sum;
}

// g with dx^3 sum_j (x_j - x_i) (x) grad W(x_i - x_j) = g I: the discrete gradient of a linear
// field with cell volumes dx^3 is g times the exact one (0.956 at h = 2 dx for the spiky gradient).
inline double lattice_gradient_consistency(double dx, double h) {
  const SpikyGradient grad_w(h);
  double sum = 0.0;
  for_each_lattice_neighbour(dx, h, [&](const Eigen::Vector3d& x_ji) { sum += x_ji.x() * grad_w(-x_ji).x(); });
  return dx * dx * dx * sum;
}

}  // namespace mssph::reference
