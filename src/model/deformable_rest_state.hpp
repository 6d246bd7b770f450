#pragma once
// The rest configuration of deformable bodies (paper 3.1.2), found once at start: rest positions,
// rest neighbour sets, rest volumes and kernel-gradient corrections. Indexed by particle over the
// whole scene; particles of other kinds have no rest neighbours. Built in double once and used by
// both precisions: the reference directly, the float backends converted (kernels/common/float_scene).
#include "model/material_law.hpp"
#include "model/neighbour_search.hpp"
#include "particle_setup.hpp"

#include <Eigen/Core>

#include <vector>

namespace mssph {

// The rest-configuration kernel gradient d_ij = V0_j L_i grad W(X_i - X_j) [m^0]: the weight of
// neighbour j in particle i's gradient estimate.
inline Eigen::Vector3d rest_gradient(double rest_volume_j, const Eigen::Matrix3d& correction_i,
                                     const Eigen::Vector3d& grad_w_rest) {
  return rest_volume_j * (correction_i * grad_w_rest);
}

// What the loop needs of one rest neighbour j of particle i, computed once.
struct RestBond {
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  // X_ij = X_j - X_i [m]
  double moment_weight = 0.0;                        // m_j W(|X_ij|), for A_i [kg/m^3]
  double kernel = 0.0;                               // W(|X_ij|) [1/m^3]
  Eigen::Vector3d d_ij = Eigen::Vector3d::Zero();    // V0_j L_i grad W(X_i - X_j) [1/m]
  Eigen::Vector3d d_ji = Eigen::Vector3d::Zero();    // V0_i L_j grad W(X_j - X_i) [1/m]
};

struct DeformableRestState {
  std::vector<Eigen::Vector3d> position;  // X_i, the initial positions [m]
  // Rest neighbours of i: particles j != i of the same deformable body with |X_ij| < h. Kept for
  // the whole run: a body's particles interact through these bonds only, whatever their distance
  // later (eq. 7 acts between bodies, not within one).
  NeighbourLists neighbours;
  std::vector<RestBond> bonds;  // aligned with neighbours.indices
  // V0_i = m_i / sum_j m_j W(|X_ij|), j over the body's own particles, i included [m^3].
  std::vector<double> volume;
  // L_i = (sum_j V0_j grad W(X_i - X_j) (x) X_ij)^-1 with kernel-gradient correction, else I.
  std::vector<Eigen::Matrix3d> correction;
  std::vector<LameParameters> lame;  // per particle, the material law of its body (material_law.hpp)
  // The own body's share of the number density behind a particle's pressure, frozen at rest:
  // delta0_own,i = W(0) + sum_j W(|X_ij|), j != i over the particles of i's body within h at rest,
  // W the spiky smoothing kernel of the density pass [1/m^3], for the particles that have one
  // (has_own_rest_number_density), else 0. See reads_contact_layer_density below.
  std::vector<double> own_rest_number_density;
};

// The density of a solid's contact layer. A deformable particle's pressure acts on other bodies
// only (eq. 7: the pressure pairs within a deformable body are skipped; elasticity holds the body
// together), so the number density behind it counts the other bodies' neighbours live and its own
// body's at rest: delta_i = sum_{j not in body(i)} W(|x_i - x_j|) + delta0_own,i. Then the
// interface pressure is the gradient of one potential, and the body's elastic compression, whose
// restoring force is elasticity's, cannot push on its neighbours a second time through pressure
// (with the own body's neighbours counted live it did, through a force that was no potential's
// gradient and fed energy into a body pressed against it: results/decisions/005-contact-layer-density.md). The same
// spirit as the frozen number density of boundary particles in Akinci et al. 2012 ("Versatile
// rigid-fluid coupling for incompressible SPH"). Rigid and boundary bodies need no special case:
// their own neighbourhoods never change, so their live own-body sum is already their rest share.
inline bool reads_contact_layer_density(BodyKind kind) { return kind == BodyKind::deformable; }

// Whose own-body number density share at rest the rest state holds: a deformable particle's, the
// frozen part of its contact layer's density, and a rigid or boundary particle's, which equals its
// live share (see above). The float backends take them from here, so the walks of rigid and
// boundary particles, like those of deformable ones, need not visit their own body
// (kernels/common/fluid_physics.hpp, takes_own_body_at_rest); the reference sums rigid and boundary
// bodies' shares live.
inline bool has_own_rest_number_density(BodyKind kind) { return kind != BodyKind::fluid; }

inline bool is_deformable(const ParticleSetup& setup, std::size_t i) {
  return setup.bodies[setup.body[i]].kind == BodyKind::deformable;
}

// Builds the rest state from the initial particles. O(N) through the grid neighbour search.
DeformableRestState build_deformable_rest_state(const ParticleSetup& setup);

// Kernel-gradient correction (Bonet and Lok 1999; Peer et al. 2018): L_i = B_i^-T with
// B_i = sum_j V0_j X_ij (x) grad W(X_i - X_j), so that sum_j X_ij (x) V0_j L_i grad W = I and the
// gradient of any linear field is exact. B_i is inverted through its SVD; singular values below
// 1e-6 of the largest (a flat or linear neighbourhood: one layer, one row) are left out
// (pseudo-inverse), so the correction acts in the directions the neighbourhood samples.
Eigen::Matrix3d kernel_gradient_correction(const Eigen::Matrix3d& b);

}  // namespace mssph
