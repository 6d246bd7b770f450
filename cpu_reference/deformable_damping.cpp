#include "deformable_damping.hpp"

#include <Eigen/SVD>

namespace mssph::reference {

RigidMotion rigid_motion_of(const ParticleSetup& setup, const ParticleState& particles, const BodySetup& body) {
  RigidMotion motion;
  double mass = 0.0;
  Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
  for (std::size_t i = body.first; i < body.first + body.count; ++i) {
    mass += setup.mass[i];
    motion.centre += setup.mass[i] * particles.position[i];
    momentum += setup.mass[i] * particles.velocity[i];
  }
  motion.centre /= mass;
  motion.velocity = momentum / mass;
  Eigen::Vector3d angular_momentum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  for (std::size_t i = body.first; i < body.first + body.count; ++i) {
    const Eigen::Vector3d r = particles.position[i] - motion.centre;
    angular_momentum += setup.mass[i] * r.cross(particles.velocity[i] - motion.velocity);
    inertia += setup.mass[i] * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  }
  // Least-squares solve: a body on one line has a singular inertia about that line, and its
  // rotation about it is then left out.
  motion.angular_velocity =
      Eigen::JacobiSVD<Eigen::Matrix3d>(inertia, Eigen::ComputeFullU | Eigen::ComputeFullV).solve(angular_momentum);
  return motion;
}

void compute_damping_forces(const ParticleSetup& setup, const ParticleState& particles, DeformableState& state) {
  for (const BodySetup& body : setup.bodies) {
    if (body.kind != BodyKind::deformable) continue;
    const double rate = body.material.damping;
    if (rate <= 0.0) {
      for (std::size_t i = body.first; i < body.first + body.count; ++i) state.damping_force[i].setZero();
      continue;
    }
    const RigidMotion reference = body.fixed_count > 0 ? RigidMotion{} : rigid_motion_of(setup, particles, body);
    for (std::size_t i = body.first; i < body.first + body.count; ++i) {
      state.damping_force[i] =
          damping_force(rate, setup.mass[i], particles.velocity[i], reference.velocity_at(particles.position[i]));
    }
  }
}

}  // namespace mssph::reference
