#pragma once
// Rigid bodies as particle sets (Solenthaler et al. 2007 unified model; paper 3.1.1 and eq. 8,
// 9): the forces on a body's particles are summed into one wrench, the body is integrated as a
// rigid body, and its particles are placed back from their body-frame offsets.
#include "model/particle_setup.hpp"
#include "particle_state.hpp"

namespace mssph::reference {

RigidBodyState make_rigid_body_state(const BodySetup& body, std::size_t index);

// Paper eq. 8, 9 without the device term: F = sum_i f_i, tau = sum_i (x_i - x_com) x f_i over the
// body's particles, from the interaction forces (a rigid body has no internal forces).
void sum_interaction_wrench(const ParticleSetup& setup, const ParticleState& particles, RigidBodyState& body);

// Paper eq. 8: F = sum_i f_i^interaction + f_device, the summed interaction force plus the haptic
// coupling's force. Float twin: kernels::rigid_body_force.
inline Eigen::Vector3d rigid_body_force(const RigidBodyState& body) {
  return body.interaction_force + body.external_force;
}

// Paper eq. 9: tau = sum_i tau_i^interaction + tau_device, about the centre of mass. Float twin:
// kernels::rigid_body_torque.
inline Eigen::Vector3d rigid_body_torque(const RigidBodyState& body) {
  return body.interaction_torque + body.external_torque;
}

// Semi-implicit (symplectic) Euler, the rigid-body counterpart of the particles' leap-frog:
//   v += (F_interaction + F_external) / M dt + g dt,   L += (tau_interaction + tau_external) dt,
//   x += v dt,   q = exp(omega dt) q with omega = I_world^-1 L (I_world = R I_body R^T).
// Integrating the angular momentum L rather than omega keeps L exactly constant without torque
// and carries the gyroscopic term omega x I omega implicitly.
void integrate_rigid_body(RigidBodyState& body, const Eigen::Vector3d& gravity, double dt);

// x_i = x_com + R r0_i, v_i = v + omega x (x_i - x_com) for the body's particles.
void place_rigid_particles(const ParticleSetup& setup, const RigidBodyState& body, ParticleState& particles);

}  // namespace mssph::reference
