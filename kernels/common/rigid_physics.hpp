#pragma once
// Rigid bodies as particle sets (Solenthaler et al. 2007; paper 3.1.1, eq. 8, 9), float32, for
// the CUDA kernels and the host build. The integration scheme is the reference's
// (cpu_reference/rigid_body_dynamics.hpp): semi-implicit Euler on the linear and angular
// momentum, orientation advanced by exp(omega dt). Eq. 8 and 9 are rigid_body_force and
// rigid_body_torque, named as their float64 twins (tests/equations/ checks each against it).
#include "compensated_position.hpp"
#include "vec_math.hpp"

#include <cstdint>

namespace mssph::kernels {

struct RigidBody {
  std::uint32_t first, count;  // canonical particle range
  float mass;                  // [kg]
  Mat3 inverse_inertia_body;   // [1/(kg m^2)]
  Vec3 position;               // centre of mass [m]
  Vec3 position_carry;         // what its last move rounded off (compensated_position.hpp) [m]
  Quat orientation;
  Vec3 velocity;            // [m/s]
  Vec3 angular_momentum;    // [kg m^2/s]
  Vec3 external_force;      // haptic coupling [N]
  Vec3 external_torque;     // [N m]
  Vec3 interaction_force;   // last step's sum over the body's particles, eq. 8 [N]
  Vec3 interaction_torque;  // about the centre of mass, eq. 9 [N m]
};

// omega = R I_body^-1 R^T L.
MSSPH_HD Vec3 angular_velocity(const RigidBody& b) {
  const Mat3 r = rotation_matrix(b.orientation);
  return r * (b.inverse_inertia_body * (transpose(r) * b.angular_momentum));
}

// One particle's share of eq. 8 and 9: its interaction force and that force's torque about the
// centre (reference: the terms of sum_interaction_wrench).
struct Wrench {
  Vec3 force;
  Vec3 torque;
};
MSSPH_HD Wrench operator+(const Wrench& a, const Wrench& b) { return {a.force + b.force, a.torque + b.torque}; }
MSSPH_HD Wrench particle_wrench(Vec3 particle_position, Vec3 force, Vec3 centre) {
  return {force, cross(particle_position - centre, force)};
}

// Paper eq. 8: F = sum_i f_i^interaction + f_device, the sum over the body's particles
// (particle_wrench, added up by the backend) plus the haptic coupling's force.
MSSPH_HD Vec3 rigid_body_force(const RigidBody& b) { return b.interaction_force + b.external_force; }

// Paper eq. 9: tau = sum_i tau_i^interaction + tau_device, about the centre of mass.
MSSPH_HD Vec3 rigid_body_torque(const RigidBody& b) { return b.interaction_torque + b.external_torque; }

// Semi-implicit Euler under the force and torque of eq. 8, 9 (reference: integrate_rigid_body),
// the centre moved by a compensated sum.
MSSPH_HD void integrate_rigid_body(RigidBody& b, Vec3 gravity, float dt) {
  b.velocity += dt * (rigid_body_force(b) * (1.0f / b.mass) + gravity);
  b.angular_momentum += dt * rigid_body_torque(b);
  add_compensated(b.position, b.position_carry, dt * b.velocity);
  const Vec3 omega = angular_velocity(b);
  const float speed = norm(omega);
  if (speed > 0.0f) b.orientation = normalized(axis_angle((1.0f / speed) * omega, speed * dt) * b.orientation);
}

// x_i = x_com + R r0_i, v_i = v + omega x (x_i - x_com).
MSSPH_HD void place_rigid_particle(const RigidBody& b, const Mat3& rotation, Vec3 omega, Vec3 rest_offset,
                                   Vec4& position, Vec4& velocity) {
  const Vec3 arm = rotation * rest_offset;
  position = make_vec4(b.position + arm, 0.0f);
  velocity = make_vec4(b.velocity + cross(omega, arm), 0.0f);
}

}  // namespace mssph::kernels
