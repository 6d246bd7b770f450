#pragma once
// Lattice calibration: the discrete SPH sums of a particle inside an infinite cubic lattice of
// spacing dx. The scene builder stores them in ParticleSetup (rest_number_density,
// gradient_consistency), so that both precisions read densities and pressure gradients against
// the same rest lattice.
#include "model/smoothing_kernels.hpp"

#include <Eigen/Core>

#include <cmath>

namespace mssph {

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

}  // namespace mssph
