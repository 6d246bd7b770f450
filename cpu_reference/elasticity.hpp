#pragma once
// Per-particle continuum mechanics of a deformable body (paper 3.1.2, eq. 4-6), as small pure
// functions with explicit inputs and outputs, in the order the loop evaluates them. The float32
// code (kernels/common/elastic_physics.hpp) has a twin of the same name for each equation's
// function: eq. 4 displacement_gradient (elastic_forces.hpp, over i's bonds), eq. 5
// cauchy_strain, green_saint_venant_strain, isotropic_stress, first_piola_kirchhoff and
// stress_action, eq. 6 elastic_force_pair, and world_deformation_gradient.
//
// Conventions, fixed by the tests in tests/deformable/:
//   X_ij = X_j - X_i (rest), x_ij = x_j - x_i (current), grad W(r) the spiky gradient of
//   r = X_i - X_j (model/smoothing_kernels.hpp), which points from i towards j.
//   (grad u)_ab = du_a / dX_b, F = I + grad u, (a (x) b)_cd = a_c b_d.
//   d_ij = V0_j L_i grad W(X_i - X_j), with L_i = I unless kernel-gradient correction is on;
//   then sum_j X_ij (x) d_ij = I exactly.
//   u_ji = R_i^T x_ij - X_ij, the displacement of j relative to i in i's rotated rest frame.
#include "config/scene.hpp"
#include "model/material_law.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>

namespace mssph::reference {

// u_ji = R_i^T x_ij - X_ij.
inline Eigen::Vector3d rotated_displacement(const Eigen::Matrix3d& rotation_i, const Eigen::Vector3d& x_ij,
                                            const Eigen::Vector3d& rest_x_ij) {
  return rotation_i.transpose() * x_ij - rest_x_ij;
}

// One neighbour's term of the displacement gradient, paper eq. 4: grad u_i = sum_j u_ji (x) d_ij
// (summed by displacement_gradient). The paper prints the volume as V0_i; the SPH quadrature
// weight of neighbour j is its own volume V0_j (Becker et al. 2009), which sits in d_ij here. The
// two agree inside a regular lattice.
inline Eigen::Matrix3d displacement_gradient_term(const Eigen::Vector3d& u_ji, const Eigen::Vector3d& d_ij) {
  return u_ji * d_ij.transpose();
}

// What a material model makes of grad u_i, in i's rotated rest frame.
struct ElasticResponse {
  Eigen::Matrix3d strain;       // stvk, neo_hookean: Green-Saint-Venant strain; corotated: Cauchy strain [-]
  Eigen::Matrix3d stress;       // stvk, neo_hookean: second Piola-Kirchhoff S; corotated: sigma = C eps [Pa]
                                // (neo_hookean: zero where F is singular or inverted)
  Eigen::Matrix3d first_piola;  // P = d psi / d(grad u) [Pa]
  double energy_density = 0.0;  // psi [J/m^3]
};

// Green-Saint-Venant strain (the paper's): eps = 1/2 (F^T F - I) = 1/2 (grad u + grad u^T + grad u^T grad u).
inline Eigen::Matrix3d green_saint_venant_strain(const Eigen::Matrix3d& grad_u) {
  return 0.5 * (grad_u + grad_u.transpose() + grad_u.transpose() * grad_u);
}

// Linear Cauchy strain (Becker et al. 2009): eps = 1/2 (grad u + grad u^T).
inline Eigen::Matrix3d cauchy_strain(const Eigen::Matrix3d& grad_u) { return 0.5 * (grad_u + grad_u.transpose()); }

// Paper eq. 5's stress: isotropic linear elasticity sigma = C eps = lambda tr(eps) I + 2 mu eps (tensor shear:
// sigma_xy = 2 mu eps_xy = mu gamma_xy).
inline Eigen::Matrix3d isotropic_stress(const Eigen::Matrix3d& eps, const LameParameters& lame) {
  return lame.lambda * eps.trace() * Eigen::Matrix3d::Identity() + 2.0 * lame.mu * eps;
}

// psi = 1/2 eps : C : eps = lambda/2 tr(eps)^2 + mu eps : eps [J/m^3].
inline double quadratic_energy_density(const Eigen::Matrix3d& eps, const LameParameters& lame) {
  const double trace = eps.trace();
  return 0.5 * lame.lambda * trace * trace + lame.mu * eps.cwiseProduct(eps).sum();
}

// St Venant-Kirchhoff (the paper's eq. 5): S = C E with the Green-Saint-Venant strain E,
// P = F S, which is the paper's (I + grad u^T) sigma in our gradient convention (the paper's
// grad u is the transpose of ours).
inline ElasticResponse saint_venant_kirchhoff(const Eigen::Matrix3d& grad_u, const LameParameters& lame) {
  ElasticResponse r;
  r.strain = green_saint_venant_strain(grad_u);
  r.stress = isotropic_stress(r.strain, lame);
  r.first_piola = (Eigen::Matrix3d::Identity() + grad_u) * r.stress;
  r.energy_density = quadratic_energy_density(r.strain, lame);
  return r;
}

// Corotated linear elasticity (Mueller and Gross 2004; Becker et al. 2009): sigma = C eps with
// the Cauchy strain of the rotated-frame gradient, P = sigma.
inline ElasticResponse corotated_linear(const Eigen::Matrix3d& grad_u, const LameParameters& lame) {
  ElasticResponse r;
  r.strain = cauchy_strain(grad_u);
  r.stress = isotropic_stress(r.strain, lame);
  r.first_piola = r.stress;
  r.energy_density = quadratic_energy_density(r.strain, lame);
  return r;
}

// The volumetric part of the compressible Neo-Hookean energy, G(J) = lambda/2 (ln J)^2 - mu ln J,
// and its derivative g = G'(J) = (lambda ln J - mu) / J; below J_e = kNeoHookeanBarrierEnd both
// follow G's second-order Taylor expansion about J_e (g' = (lambda (1 - ln J) + mu) / J^2 > 0
// there, so the continued g keeps decreasing: the push-back still grows as J shrinks).
struct VolumetricTerm {
  double energy = 0.0;      // G [J/m^3]
  double derivative = 0.0;  // g = dG/dJ [Pa]
};

inline VolumetricTerm neo_hookean_volumetric(double j, const LameParameters& lame) {
  const auto exact = [&](double x) {
    const double log_x = std::log(x);
    return VolumetricTerm{0.5 * lame.lambda * log_x * log_x - lame.mu * log_x, (lame.lambda * log_x - lame.mu) / x};
  };
  if (j >= kNeoHookeanBarrierEnd) return exact(j);
  const double je = kNeoHookeanBarrierEnd;
  const VolumetricTerm at = exact(je);
  const double curvature = (lame.lambda * (1.0 - std::log(je)) + lame.mu) / (je * je);
  const double dj = j - je;
  return {at.energy + at.derivative * dj + 0.5 * curvature * dj * dj, at.derivative + curvature * dj};
}

// Compressible Neo-Hookean (Bonet and Wood 2008, eq. 6.27-6.28):
//   psi = mu/2 (tr(F^T F) - 3) - mu ln J + lambda/2 (ln J)^2,  P = mu (F - F^-T) + lambda ln J F^-T,
// written as P = mu F + g(J) cof F with cof F = J F^-T, which needs no inverse; S = F^-1 P.
// At small strain it is linear elasticity with the same lambda and mu.
inline ElasticResponse neo_hookean(const Eigen::Matrix3d& grad_u, const LameParameters& lame) {
  const Eigen::Matrix3d f = Eigen::Matrix3d::Identity() + grad_u;
  Eigen::Matrix3d cofactor;
  cofactor.col(0) = f.col(1).cross(f.col(2));
  cofactor.col(1) = f.col(2).cross(f.col(0));
  cofactor.col(2) = f.col(0).cross(f.col(1));
  const double j = f.col(0).dot(cofactor.col(0));
  const VolumetricTerm volumetric = neo_hookean_volumetric(j, lame);
  ElasticResponse r;
  r.strain = green_saint_venant_strain(grad_u);
  r.first_piola = lame.mu * f + volumetric.derivative * cofactor;
  // S = mu I + g J C^-1, C^-1 = cof^T cof / J^2.
  r.stress = j > 0.0 ? Eigen::Matrix3d(lame.mu * Eigen::Matrix3d::Identity() +
                                       (volumetric.derivative / j) * cofactor.transpose() * cofactor)
                     : Eigen::Matrix3d::Zero();
  r.energy_density = 0.5 * lame.mu * (f.squaredNorm() - 3.0) + volumetric.energy;
  return r;
}

inline ElasticResponse elastic_response(const Eigen::Matrix3d& grad_u, const LameParameters& lame, ElasticModel model) {
  switch (model) {
    case ElasticModel::corotated_linear:
      return corotated_linear(grad_u, lame);
    case ElasticModel::neo_hookean:
      return neo_hookean(grad_u, lame);
    case ElasticModel::saint_venant_kirchhoff:
      break;
  }
  return saint_venant_kirchhoff(grad_u, lame);
}

// Paper eq. 5 up to its volumes: P = d psi / d(grad u) of the material model, alone (the float
// code computes P only; the reference's loop also keeps strain, stress and energy).
inline Eigen::Matrix3d first_piola_kirchhoff(const Eigen::Matrix3d& grad_u, const LameParameters& lame,
                                             ElasticModel model) {
  return elastic_response(grad_u, lame, model).first_piola;
}

// Kelvin-Voigt viscous stress in i's rotated rest frame, sigma_v = tau C : eps_dot with the strain
// rate eps_dot = 1/2 (grad v + grad v^T) and the retardation time tau = eta / E of the viscous
// modulus eta [Pa s] (Christensen, Theory of Viscoelasticity, 1982, sec. 1.3): under uniaxial
// stress sigma = E eps + eta eps_dot, and each vibration mode of angular frequency omega decays
// with damping ratio eta omega / (2 E).
inline Eigen::Matrix3d viscous_stress(const Eigen::Matrix3d& grad_v, const LameParameters& lame,
                                      double retardation_time) {
  return retardation_time * isotropic_stress(cauchy_strain(grad_v), lame);
}

// The viscous stress taken as a second Piola-Kirchhoff stress and added to P as F sigma_v, with
// F = I + grad u, as the St Venant-Kirchhoff stress is: K_i F_i^T stays symmetric, so with
// kernel-gradient correction the viscous forces exert no net torque.
inline Eigen::Matrix3d viscous_first_piola(const Eigen::Matrix3d& grad_u, const Eigen::Matrix3d& viscous) {
  return (Eigen::Matrix3d::Identity() + grad_u) * viscous;
}

// The volume ratio J = det F = det(I + grad u) of i's neighbourhood [-] (R_i has det 1): the
// compression measure of the run log.
inline double volume_ratio(const Eigen::Matrix3d& grad_u) {
  return (Eigen::Matrix3d::Identity() + grad_u).determinant();
}

// The world-frame deformation gradient F_i = R_i (I + grad u_i) of i's neighbourhood.
inline Eigen::Matrix3d world_deformation_gradient(const Eigen::Matrix3d& rotation_i, const Eigen::Matrix3d& grad_u) {
  return rotation_i * (Eigen::Matrix3d::Identity() + grad_u);
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
inline Eigen::Vector3d elastic_force_pair(const Eigen::Matrix3d& action_i, const Eigen::Vector3d& d_ij,
                                          const Eigen::Matrix3d& action_j, const Eigen::Vector3d& d_ji) {
  return action_i * d_ij - action_j * d_ji;
}

}  // namespace mssph::reference
