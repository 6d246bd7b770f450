#pragma once
// Per-particle continuum mechanics of a deformable body (paper 3.1.2, eq. 4-6), as small pure
// functions with explicit inputs and outputs, in the order the loop evaluates them.
//
// Conventions, fixed by the tests in tests/deformable/:
//   X_ij = X_j - X_i (rest), x_ij = x_j - x_i (current), grad W(r) the spiky gradient of
//   r = X_i - X_j (sph_kernels.hpp), which points from i towards j.
//   (grad u)_ab = du_a / dX_b, F = I + grad u, (a (x) b)_cd = a_c b_d.
//   d_ij = V0_j L_i grad W(X_i - X_j), with L_i = I unless kernel-gradient correction is on;
//   then sum_j X_ij (x) d_ij = I exactly.
//   u_ji = R_i^T x_ij - X_ij, the displacement of j relative to i in i's rotated rest frame.
#include "config/scene.hpp"

#include <Eigen/Core>

namespace mssph::reference {

struct LameParameters {
  double lambda = 0.0;  // [Pa]
  double mu = 0.0;      // shear modulus [Pa]
};

// The rest-configuration kernel gradient d_ij = V0_j L_i grad W(X_i - X_j) [m^0]: the weight of
// neighbour j in particle i's gradient estimate.
inline Eigen::Vector3d rest_gradient(double rest_volume_j, const Eigen::Matrix3d& correction_i,
                                     const Eigen::Vector3d& grad_w_rest) {
  return rest_volume_j * (correction_i * grad_w_rest);
}

// u_ji = R_i^T x_ij - X_ij.
inline Eigen::Vector3d rotated_displacement(const Eigen::Matrix3d& rotation_i, const Eigen::Vector3d& x_ij,
                                            const Eigen::Vector3d& rest_x_ij) {
  return rotation_i.transpose() * x_ij - rest_x_ij;
}

// One neighbour's term of the displacement gradient, paper eq. 4: grad u_i = sum_j u_ji (x) d_ij.
// The paper prints the volume as V0_i; the SPH quadrature weight of neighbour j is its own volume
// V0_j (Becker et al. 2009), which sits in d_ij here. The two agree inside a regular lattice.
inline Eigen::Matrix3d displacement_gradient_term(const Eigen::Vector3d& u_ji, const Eigen::Vector3d& d_ij) {
  return u_ji * d_ij.transpose();
}

// Green-Saint-Venant strain (the paper's): eps = 1/2 (F^T F - I) = 1/2 (grad u + grad u^T + grad u^T grad u).
inline Eigen::Matrix3d green_saint_venant_strain(const Eigen::Matrix3d& grad_u) {
  return 0.5 * (grad_u + grad_u.transpose() + grad_u.transpose() * grad_u);
}

// Linear Cauchy strain (Becker et al. 2009): eps = 1/2 (grad u + grad u^T).
inline Eigen::Matrix3d cauchy_strain(const Eigen::Matrix3d& grad_u) { return 0.5 * (grad_u + grad_u.transpose()); }

inline Eigen::Matrix3d strain(const Eigen::Matrix3d& grad_u, StrainMeasure measure) {
  return measure == StrainMeasure::cauchy ? cauchy_strain(grad_u) : green_saint_venant_strain(grad_u);
}

// Isotropic linear elasticity sigma = C eps = lambda tr(eps) I + 2 mu eps (tensor shear:
// sigma_xy = 2 mu eps_xy = mu gamma_xy). With Green-Saint-Venant strain this is the second
// Piola-Kirchhoff stress of a St Venant-Kirchhoff material.
inline Eigen::Matrix3d isotropic_stress(const Eigen::Matrix3d& eps, const LameParameters& lame) {
  return lame.lambda * eps.trace() * Eigen::Matrix3d::Identity() + 2.0 * lame.mu * eps;
}

// Strain energy density psi = 1/2 eps : C : eps = lambda/2 tr(eps)^2 + mu eps : eps [J/m^3].
inline double strain_energy_density(const Eigen::Matrix3d& eps, const LameParameters& lame) {
  const double trace = eps.trace();
  return 0.5 * lame.lambda * trace * trace + lame.mu * eps.cwiseProduct(eps).sum();
}

// First Piola-Kirchhoff stress P = d psi / d(grad u): F sigma for Green-Saint-Venant strain,
// sigma itself for Cauchy strain. This is the paper's (I + grad u^T) sigma of eq. 5 in our
// gradient convention (the paper's grad u is the transpose of ours).
inline Eigen::Matrix3d first_piola_kirchhoff(const Eigen::Matrix3d& grad_u, const Eigen::Matrix3d& sigma,
                                             StrainMeasure measure) {
  if (measure == StrainMeasure::cauchy) return sigma;
  return (Eigen::Matrix3d::Identity() + grad_u) * sigma;
}

// K_i = V0_i R_i P_i, the world-frame matrix through which particle i's strain energy
// U_i = V0_i psi_i pushes on its neighbours: the force on neighbour j from U_i is
// R_i f_ji = -K_i d_ij (paper eq. 5, f_ji = -V0_i P_i d_ij: eq. 5's factor 2 cancels eq. 6's 1/2),
// and the force on i itself from U_i is +sum_j K_i d_ij.
inline Eigen::Matrix3d stress_action(double rest_volume_i, const Eigen::Matrix3d& rotation_i,
                                     const Eigen::Matrix3d& first_piola) {
  return rest_volume_i * rotation_i * first_piola;
}

// One neighbour's term of the symmetrised elastic force on i, paper eq. 6:
//   f_i = sum_j (-R_i f_ji + R_j f_ij) = sum_j (K_i d_ij - K_j d_ji).
// Each pair term appears with opposite sign in j's sum, so the forces sum to zero over a body.
inline Eigen::Vector3d elastic_force_term(const Eigen::Matrix3d& action_i, const Eigen::Vector3d& d_ij,
                                          const Eigen::Matrix3d& action_j, const Eigen::Vector3d& d_ji) {
  return action_i * d_ij - action_j * d_ji;
}

}  // namespace mssph::reference
