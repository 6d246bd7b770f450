#pragma once
// Zero-energy-mode (hourglass) control for SPH elasticity after Ganzenmueller 2015 ("An hourglass
// control algorithm for Lagrangian Smooth Particle Hydrodynamics", CMAME 286). The SPH
// displacement gradient is blind to some particle patterns (e.g. neighbouring particles
// displaced in opposite directions on a lattice): they change no grad u_i, cost no strain
// energy and grow unresisted. The control adds a pair force that pulls each pair towards the
// position its particles' deformation gradients predict. Off when zero_energy_stiffness = 0.
#include "deformable_state.hpp"
#include "model/deformable_rest_state.hpp"
#include "model/particle_setup.hpp"

#include <Eigen/Core>

#include <vector>

namespace mssph::reference {

// One neighbour's control force on i (Ganzenmueller 2015, in our notation; float twin
// kernels::zero_energy_force_pair):
//   error of the pair as seen from i:  e_i = F_i X_ij - x_ij,  from j: e_j = F_j X_ij - x_ij
//   (world-frame F = R (I + grad u)), projected on the current pair direction n = x_ij / |x_ij|:
//   delta = (e_i + e_j) . n,
//   f_i = -(alpha / 2) V0_i V0_j W(|X_ij|) E delta / |X_ij|^2 n.
// delta > 0 means the pair is closer than its neighbourhoods' deformation says: i is pushed
// away from j. The force is central and antisymmetric in (i, j): linear and angular momentum are
// conserved. With kernel-gradient correction a linear deformation has e = 0 exactly and feels no
// control force; without it, e is a few per cent of the strain and the control adds that much
// stiffness (times alpha) to uniform deformations.
inline Eigen::Vector3d zero_energy_force_pair(const Eigen::Matrix3d& world_f_i, const Eigen::Matrix3d& world_f_j,
                                              const Eigen::Vector3d& rest_x_ij, const Eigen::Vector3d& x_ij,
                                              double rest_volumes, double w_rest, double young_modulus, double alpha) {
  const double r = x_ij.norm();
  if (r <= 0.0) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d n = x_ij / r;
  const double delta = ((world_f_i + world_f_j) * rest_x_ij - 2.0 * x_ij).dot(n);
  return (-0.5 * alpha * rest_volumes * w_rest * young_modulus * delta / rest_x_ij.squaredNorm()) * n;
}

// The control forces of every deformable particle whose body has zero_energy_stiffness > 0
// (alpha), from the rotations and displacement gradients of the current step.
void compute_zero_energy_forces(const ParticleSetup& setup, const DeformableRestState& rest,
                                const std::vector<Eigen::Vector3d>& positions, DeformableState& state);

}  // namespace mssph::reference
