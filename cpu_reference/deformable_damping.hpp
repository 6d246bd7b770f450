#pragma once
// Mass-proportional damping of deformable bodies (Rayleigh damping C = gamma M), off when the
// material's damping rate gamma [1/s] is 0. Each vibration mode of the body then decays with
// amplitude exp(-gamma t / 2) and energy exp(-gamma t), whatever its frequency.
//
// The force damps velocity relative to the body's rigid motion, f_i = -gamma m_i (v_i - v_ref(x_i)):
// for a body held by fixed regions v_ref = 0 (it is attached to the world); for a free body
// v_ref = v_com + omega x (x - x_com), its mean translation and rotation (omega = I^-1 L from the
// particles). Damping against absolute velocity would act like air drag, slowing a falling or
// spinning body; this form damps deformation only and keeps a free body's linear and angular
// momentum.
#include "deformable_state.hpp"
#include "model/particle_setup.hpp"
#include "particle_state.hpp"

#include <Eigen/Core>

namespace mssph::reference {

// The rigid motion that best fits a set of particle velocities in the least-squares, mass-weighted
// sense: same mass, centre, linear and angular momentum.
struct RigidMotion {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();            // [m]
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          // of the centre [m/s]
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // [rad/s]
  Eigen::Vector3d velocity_at(const Eigen::Vector3d& x) const { return velocity + angular_velocity.cross(x - centre); }
};

RigidMotion rigid_motion_of(const ParticleSetup& setup, const ParticleState& particles, const BodySetup& body);

// f_i = -gamma m_i (v_i - v_ref). Float twin: kernels::damping_force (v_ref = 0 there).
inline Eigen::Vector3d damping_force(double rate, double mass, const Eigen::Vector3d& velocity,
                                     const Eigen::Vector3d& reference_velocity) {
  return -rate * mass * (velocity - reference_velocity);
}

// Fills state.damping_force for every deformable particle (zero where damping is off). The
// velocities are the leap-frog's v_{n-1/2}: explicit, first order in gamma dt.
void compute_damping_forces(const ParticleSetup& setup, const ParticleState& particles, DeformableState& state);

}  // namespace mssph::reference
