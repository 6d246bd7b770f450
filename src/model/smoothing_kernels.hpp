#pragma once
// Smoothing kernels of Mueller, Charypar and Gross 2003 ("Particle-based fluid simulation for
// interactive applications"), double precision, support radius h: W = 0 for r >= h.
// Each kernel is one small class with its constants computed once. The model's lattice
// calibration and rest state and the reference backend use them; the float backends have their
// float32 twins in kernels/common/smoothing_kernels.hpp.
#include <Eigen/Core>

#include <cmath>
#include <numbers>

namespace mssph {

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

}  // namespace mssph
