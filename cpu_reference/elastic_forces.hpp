#pragma once
// The loops of corotated SPH elasticity (paper 3.1.2, eq. 4-6) over the deformable particles:
// step 1 (rotations), the elastic part of step 2 (strain and stress) and of step 3 (forces).
// The per-particle math is in corotation.hpp and elasticity.hpp.
#include "deformable_state.hpp"
#include "model/deformable_rest_state.hpp"
#include "model/particle_setup.hpp"

#include <Eigen/Core>

#include <vector>

namespace mssph::reference {

// The moment matrix A_i = sum_j m_j W(|X_ij|) x_ij X_ij^T over i's rest bonds, whose rotational
// part is R_i (float: the moment of kernels::bond_sums).
Eigen::Matrix3d moment_matrix(const DeformableRestState& rest, const std::vector<Eigen::Vector3d>& positions,
                              std::size_t i);

// Paper eq. 4 over i's rest bonds: grad u_i = sum_j (R_i^T x_ij - X_ij) (x) d_ij. Float twin:
// kernels::displacement_gradient, which splits the sum in two halves gathered with A_i.
Eigen::Matrix3d displacement_gradient(const Eigen::Matrix3d& rotation_i, const DeformableRestState& rest,
                                      const std::vector<Eigen::Vector3d>& positions, std::size_t i);

// The velocity gradient in i's rotated rest frame, eq. 4's operator on the velocities:
// grad v_i = sum_j (R_i^T v_ij) (x) d_ij, v_ij = v_j - v_i. With kernel-gradient correction a
// rigid motion v_ij = w x x_ij gives a skew grad v_i, hence no strain rate. Float twin:
// kernels::velocity_gradient.
Eigen::Matrix3d velocity_gradient(const Eigen::Matrix3d& rotation_i, const DeformableRestState& rest,
                                  const std::vector<Eigen::Vector3d>& velocities, std::size_t i);

// Step 1: R_i = rotational part of A_i = sum_j m_j W(|X_ij|) x_ij X_ij^T over i's rest
// neighbours (state.rotation holds last step's R_i on entry, used only for degenerate A_i).
void compute_rotations(const ParticleSetup& setup, const DeformableRestState& rest,
                       const std::vector<Eigen::Vector3d>& positions, DeformableState& state);

// Step 2, elastic properties: grad u_i (eq. 4), strain, stress, the Kelvin-Voigt viscous stress
// where the body has a viscous modulus, K_i = V0_i R_i (P_i + sigma_v,i) and the strain energy
// V0_i psi_i, from the rotations of step 1 and the velocities v_{n-1/2}.
void compute_elastic_stresses(const ParticleSetup& setup, const DeformableRestState& rest,
                              const std::vector<Eigen::Vector3d>& positions,
                              const std::vector<Eigen::Vector3d>& velocities, DeformableState& state);

// Step 3: the symmetrised elastic forces of eq. 6, f_i = sum_j (K_i d_ij - K_j d_ji), gathered
// per particle (no scattered writes).
void compute_elastic_forces(const ParticleSetup& setup, const DeformableRestState& rest, DeformableState& state);

// Total strain energy sum_i V0_i psi_i of one body [J] (from the last compute_elastic_stresses).
double body_strain_energy(const ParticleSetup& setup, const DeformableState& state, std::size_t body);

}  // namespace mssph::reference
