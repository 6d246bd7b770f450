#pragma once
// Step 3 of the loop (paper 3.2), pressure and viscosity: inside fluids (paper eq. 2, 3) and
// between particles of different bodies of any kind (paper eq. 7, the whole coupling between
// media).
#include "model/neighbour_search.hpp"
#include "model/particle_setup.hpp"
#include "particle_state.hpp"

#include <Eigen/Core>

namespace mssph::reference {

// Pressure force, paper eq. 2 in its energy-consistent form, one neighbour's term:
//   f_i = -(1 / g) sum_j (V_i^2 P_i + V_j^2 P_j) grad W(x_i - x_j),
// the negative gradient of the internal energy sum_i m_i e(rho_i) for the densities of
// density.hpp (Solenthaler and Pajarola 2008, eq. 5), up to the constant 1 / g. Eq. 2 as printed,
// -V_i sum_j V_j (P_i + P_j) / 2 grad W, differs in two ways the tests reject: its 1/2 makes it feel
// half the pressure gradient (for P = a.x, sum_j V_j (P_i + P_j)/2 grad W_ij ~= a/2 inside a
// lattice, since sum_j V_j grad W_ij ~= 0 and sum_j V_j (x_j - x_i) (x) grad W_ij ~= I), so a settled
// column would carry twice the hydrostatic pressure; and V_i V_j in place of V_i^2, V_j^2 is not a
// gradient of any energy at interfaces. g (lattice_gradient_consistency, 0.956 at h = 2 dx)
// makes the gradient of a linear field exact inside a rest lattice. Pinned by the
// hydrostatic-column and floating-sphere tests. Float twin: kernels::pressure_force_pair.
inline Eigen::Vector3d pressure_force_pair(double volume_i, double pressure_i, double volume_j, double pressure_j,
                                           double gradient_consistency, const Eigen::Vector3d& grad_w) {
  return -((volume_i * volume_i * pressure_i + volume_j * volume_j * pressure_j) / gradient_consistency) * grad_w;
}

// Viscosity force, paper eq. 3, one neighbour's term: f_i = mu V_i sum_j V_j (v_j - v_i) lap W(|x_i - x_j|).
// Float twin: kernels::viscosity_force_pair.
inline Eigen::Vector3d viscosity_force_pair(double mu, double volume_i, double volume_j, double laplacian,
                                            const Eigen::Vector3d& velocity_i, const Eigen::Vector3d& velocity_j) {
  return mu * volume_i * volume_j * laplacian * (velocity_j - velocity_i);
}

// The velocity gradient of a fluid particle for the full_stress viscosity, corrected so that it is
// exact for any linear velocity field on any particle arrangement (Bonet and Lok 1999):
//   A_i = G_i M_i^-1, G_i = sum_j V_j (v_j - v_i) (x) grad W_ij, M_i = sum_j V_j (x_j - x_i) (x) grad W_ij,
// over the neighbours whose pair viscosity is not zero. Float twin: kernels::VelocityGradientSums.
struct VelocityGradientSums {
  Eigen::Matrix3d velocity_moment = Eigen::Matrix3d::Zero();  // G_i [1/s]
  Eigen::Matrix3d position_moment = Eigen::Matrix3d::Zero();  // M_i [-]

  void add(double volume_j, const Eigen::Vector3d& velocity_ji, const Eigen::Vector3d& position_ji,
           const Eigen::Vector3d& grad_w) {
    velocity_moment += volume_j * velocity_ji * grad_w.transpose();
    position_moment += volume_j * position_ji * grad_w.transpose();
  }
  Eigen::Matrix3d gradient() const;  // A_i; zero where M_i is singular (no neighbours)
};

// The full_stress viscosity's second part, one neighbour's term: the divergence of the stress
// mu (grad u)^T in the pair form of eq. 2 (pressure_force_pair, with sigma = mu A^T for -P I):
//   f_i = mu (V_i^2 A_i^T + V_j^2 A_j^T) grad W_ij / g.
// Inside an incompressible fluid it is mu grad(div u), zero; across a surface it carries the
// traction mu (grad u)^T n that eq. 3 leaves out, a third of a turning sphere's torque. A rigid,
// deformable or boundary particle meeting a fluid one takes the fluid's A (traction continuous
// across the contact). Float twin: kernels::transposed_stress_force_pair.
inline Eigen::Vector3d transposed_stress_force_pair(double mu, double volume_i, const Eigen::Matrix3d& gradient_i,
                                                    double volume_j, const Eigen::Matrix3d& gradient_j,
                                                    double gradient_consistency, const Eigen::Vector3d& grad_w) {
  return (mu / gradient_consistency) *
         (volume_i * volume_i * gradient_i.transpose() + volume_j * volume_j * gradient_j.transpose()) * grad_w;
}

// The mu of eq. 3 between bodies: the harmonic mean 2 mu_i mu_j / (mu_i + mu_j) of the two bodies'
// viscosities (Morris et al. 1997), so a body of zero viscosity, e.g. a free-slip wall, exerts no
// friction. Float twin: kernels::interface_viscosity.
inline double interface_viscosity(double mu_i, double mu_j) {
  return mu_i + mu_j > 0.0 ? 2.0 * mu_i * mu_j / (mu_i + mu_j) : 0.0;
}

// Paper eq. 7: between particles of different bodies the interaction force is the pressure and
// viscosity force of eq. 2 and 3. Float twin: kernels::interaction_force.
inline Eigen::Vector3d interaction_force(const Eigen::Vector3d& pressure, const Eigen::Vector3d& viscosity) {
  return pressure + viscosity;
}

// The pressure and viscosity forces of all particles. Forces between particles of one fluid body
// go to internal_force, forces between particles of different bodies to interaction_force.
// Rigid, deformable and boundary bodies feel no pressure or viscosity from their own particles
// (their internal forces are rigidity and elasticity). Boundary particles receive no force.
// With the full_stress viscosity, the transposed stress term joins the viscosity part of both; it
// reads the velocity gradients of compute_velocity_gradients.
void compute_pressure_viscosity_forces(const ParticleSetup& setup, const NeighbourLists& neighbours,
                                       ParticleState& state);

// Each fluid particle's corrected velocity gradient A_i (VelocityGradientSums), zero for the others;
// for the full_stress viscosity.
void compute_velocity_gradients(const ParticleSetup& setup, const NeighbourLists& neighbours, ParticleState& state);

}  // namespace mssph::reference
