#include "rigid_body_dynamics.hpp"

#include <cmath>

namespace mssph::reference {

RigidBodyState make_rigid_body_state(const BodySetup& body, std::size_t index) {
  RigidBodyState state;
  state.body = index;
  state.mass = body.mass;
  state.inertia_body = body.inertia_body;
  state.inertia_body_inverse = body.inertia_body.inverse();
  state.position = body.centre_of_mass;
  state.orientation = body.orientation;
  state.velocity = body.velocity;
  const Eigen::Matrix3d r = body.orientation.toRotationMatrix();
  state.angular_momentum = r * body.inertia_body * r.transpose() * body.angular_velocity;
  return state;
}

void sum_interaction_wrench(const ParticleSetup& setup, const ParticleState& particles, RigidBodyState& body) {
  const BodySetup& b = setup.bodies[body.body];
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
  for (std::size_t i = b.first; i < b.first + b.count; ++i) {
    force += particles.interaction_force[i];
    torque += (particles.position[i] - body.position).cross(particles.interaction_force[i]);
  }
  body.interaction_force = force;
  body.interaction_torque = torque;
}

void integrate_rigid_body(RigidBodyState& body, const Eigen::Vector3d& gravity, double dt) {
  body.velocity += (rigid_body_force(body) / body.mass + gravity) * dt;
  body.angular_momentum += rigid_body_torque(body) * dt;
  body.position += body.velocity * dt;
  const Eigen::Vector3d omega = body.angular_velocity();
  const double angle = omega.norm() * dt;
  if (angle > 0.0) {
    const Eigen::Quaterniond increment(Eigen::AngleAxisd(angle, omega.normalized()));
    body.orientation = (increment * body.orientation).normalized();
  }
}

void place_rigid_particles(const ParticleSetup& setup, const RigidBodyState& body, ParticleState& particles) {
  const BodySetup& b = setup.bodies[body.body];
  const Eigen::Matrix3d r = body.orientation.toRotationMatrix();
  const Eigen::Vector3d omega = body.angular_velocity();
  for (std::size_t i = b.first; i < b.first + b.count; ++i) {
    const Eigen::Vector3d arm = r * setup.rest_offset[i];
    particles.position[i] = body.position + arm;
    particles.velocity[i] = body.velocity + omega.cross(arm);
  }
}

}  // namespace mssph::reference
