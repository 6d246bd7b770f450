// Paper eq. 8 and 9 and the rigid-body integration, float32 (kernels/common/rigid_physics.hpp)
// against the float64 twins of the same names (cpu_reference/rigid_body_dynamics.hpp,
// particle_state.hpp). Method and tolerance: twin_support.hpp. Bodies of 0.1-10 kg with inertias
// of a 10 cm object, forces up to 100 N, steps of 0.1-2 ms.
#include "common/rigid_physics.hpp"
#include "rigid_body_dynamics.hpp"
#include "twin_support.hpp"

#include <Eigen/LU>

#include <vector>

namespace mssph::testing {
namespace {

// One random rigid body in both precisions (same float32 values).
struct TwinBody {
  reference::RigidBodyState reference;
  kernels::RigidBody kernel{};
};

TwinBody draw_body(TwinDraws& draws) {
  TwinBody b;
  reference::RigidBodyState& r = b.reference;
  r.mass = draws.uniform(0.1, 10.0);
  const Eigen::Matrix3d axes = draws.rotation();
  const Eigen::Vector3d moments(draws.uniform(1e-3, 1e-2), draws.uniform(1e-3, 1e-2), draws.uniform(1e-3, 1e-2));
  r.inertia_body_inverse = TwinDraws::rounded(axes * moments.cwiseInverse().asDiagonal() * axes.transpose());
  r.inertia_body = r.inertia_body_inverse.inverse();  // unused by the step; kept consistent
  r.position = draws.vector(1.0);
  r.orientation = draws.quaternion();
  r.velocity = draws.vector(2.0);
  r.angular_momentum = draws.vector(0.1);
  r.external_force = draws.vector(100.0);
  r.external_torque = draws.vector(5.0);
  r.interaction_force = draws.vector(100.0);
  r.interaction_torque = draws.vector(5.0);

  kernels::RigidBody& k = b.kernel;
  k.mass = static_cast<float>(r.mass);
  k.inverse_inertia_body = to_float(r.inertia_body_inverse);
  k.position = to_float(r.position);
  k.orientation = to_float(r.orientation);
  k.velocity = to_float(r.velocity);
  k.angular_momentum = to_float(r.angular_momentum);
  k.external_force = to_float(r.external_force);
  k.external_torque = to_float(r.external_torque);
  k.interaction_force = to_float(r.interaction_force);
  k.interaction_torque = to_float(r.interaction_torque);
  return b;
}

TEST(RigidEquationTwins, ForceAndTorque) {
  TwinDraws draws("RigidEquationTwins.ForceAndTorque");
  TwinComparison force("F = sum f_interaction + f_device (eq. 8)", 0.8);  // the two may nearly cancel
  TwinComparison torque("tau = sum tau_interaction + tau_device (eq. 9)", 0.8);
  for (int k = 0; k < kDraws; ++k) {
    const TwinBody b = draw_body(draws);
    force.add(to_double(kernels::rigid_body_force(b.kernel)), reference::rigid_body_force(b.reference),
              b.reference.interaction_force.norm() + b.reference.external_force.norm());
    torque.add(to_double(kernels::rigid_body_torque(b.kernel)), reference::rigid_body_torque(b.reference),
               b.reference.interaction_torque.norm() + b.reference.external_torque.norm());
  }
}

// The sums of eq. 8, 9 over a body's particles: kernels::particle_wrench added up (as the
// backends' reductions do, in another order on a GPU) against reference::sum_interaction_wrench.
TEST(RigidEquationTwins, InteractionWrenchSums) {
  TwinDraws draws("RigidEquationTwins.InteractionWrenchSums");
  TwinComparison force("sum of particle forces (eq. 8)");
  TwinComparison torque("sum of particle torques (eq. 9)");
  for (int k = 0; k < kDraws / 10; ++k) {
    const std::size_t count = static_cast<std::size_t>(draws.uniform(1.0, 200.0));
    ParticleSetup setup;
    setup.bodies.resize(1);
    setup.bodies[0].first = 0;
    setup.bodies[0].count = count;
    reference::ParticleState particles;
    particles.resize(count);
    reference::RigidBodyState body;
    body.position = draws.vector(1.0);
    kernels::Wrench sum{{0, 0, 0}, {0, 0, 0}};
    double force_scale = 0.0, torque_scale = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
      particles.position[i] = TwinDraws::rounded(body.position + draws.vector(0.1));
      // A common push plus noise, so the sums do not cancel to nothing.
      particles.interaction_force[i] = TwinDraws::rounded(Eigen::Vector3d(1.0, -2.0, 3.0) + draws.vector(3.0));
      sum = sum + kernels::particle_wrench(to_float(particles.position[i]), to_float(particles.interaction_force[i]),
                                           to_float(body.position));
      force_scale += particles.interaction_force[i].norm();
      torque_scale += (particles.position[i] - body.position).norm() * particles.interaction_force[i].norm();
    }
    reference::sum_interaction_wrench(setup, particles, body);
    force.add(to_double(sum.force), body.interaction_force, force_scale);
    torque.add(to_double(sum.torque), body.interaction_torque, torque_scale);
  }
}

TEST(RigidEquationTwins, AngularVelocity) {
  TwinDraws draws("RigidEquationTwins.AngularVelocity");
  TwinComparison omega("omega = R I^-1 R^T L");
  for (int k = 0; k < kDraws; ++k) {
    const TwinBody b = draw_body(draws);
    omega.add(to_double(kernels::angular_velocity(b.kernel)), b.reference.angular_velocity(),
              b.reference.inertia_body_inverse.norm() * b.reference.angular_momentum.norm());
  }
}

// One semi-implicit Euler step under eq. 8, 9. Orientations are compared through the change of
// the rotation matrix in the step (|omega| dt of 0.01 to 0.3 rad, far above the tolerance).
TEST(RigidEquationTwins, IntegrateRigidBody) {
  TwinDraws draws("RigidEquationTwins.IntegrateRigidBody");
  TwinComparison velocity("velocity after a step");
  TwinComparison momentum("angular momentum after a step");
  TwinComparison position("position after a step");
  TwinComparison turn("rotation matrix change in a step");
  for (int k = 0; k < kDraws; ++k) {
    TwinBody b = draw_body(draws);
    const Eigen::Vector3d gravity = draws.vector(10.0);
    const double dt = draws.uniform(1e-4, 2e-3);
    // Angular momentum scaled so that |omega| dt is 0.01 to 0.3 rad.
    const double turn_angle = draws.uniform(0.01, 0.3);
    b.reference.angular_momentum =
        TwinDraws::rounded(b.reference.angular_momentum * (turn_angle / (b.reference.angular_velocity().norm() * dt)));
    b.kernel.angular_momentum = to_float(b.reference.angular_momentum);
    const Eigen::Matrix3d before = b.reference.orientation.toRotationMatrix();
    const double velocity_scale =
        b.reference.velocity.norm() +
        dt * ((b.reference.interaction_force.norm() + b.reference.external_force.norm()) / b.reference.mass +
              gravity.norm());
    const double momentum_scale = b.reference.angular_momentum.norm() +
                                  dt * (b.reference.interaction_torque.norm() + b.reference.external_torque.norm());
    reference::integrate_rigid_body(b.reference, gravity, dt);
    kernels::integrate_rigid_body(b.kernel, to_float(gravity), static_cast<float>(dt));
    velocity.add(to_double(b.kernel.velocity), b.reference.velocity, velocity_scale);
    momentum.add(to_double(b.kernel.angular_momentum), b.reference.angular_momentum, momentum_scale);
    position.add(to_double(b.kernel.position), b.reference.position,
                 b.reference.position.norm() + dt * b.reference.velocity.norm());
    turn.add(to_double(kernels::rotation_matrix(b.kernel.orientation)) - before,
             b.reference.orientation.toRotationMatrix() - before, 1.0);
  }
}

// x_i = x_com + R r0_i, v_i = v + omega x (x_i - x_com).
TEST(RigidEquationTwins, PlaceRigidParticle) {
  TwinDraws draws("RigidEquationTwins.PlaceRigidParticle");
  TwinComparison position("rigid particle position");
  TwinComparison velocity("rigid particle velocity");
  for (int k = 0; k < kDraws; ++k) {
    const TwinBody b = draw_body(draws);
    ParticleSetup setup;
    setup.bodies.resize(1);
    setup.bodies[0].first = 0;
    setup.bodies[0].count = 1;
    setup.rest_offset = {draws.vector(0.1)};
    reference::ParticleState particles;
    particles.resize(1);
    reference::place_rigid_particles(setup, b.reference, particles);
    kernels::Vec4 x{}, v{};
    kernels::place_rigid_particle(b.kernel, kernels::rotation_matrix(b.kernel.orientation),
                                  kernels::angular_velocity(b.kernel), to_float(setup.rest_offset[0]), x, v);
    position.add(to_double(kernels::xyz(x)), particles.position[0],
                 b.reference.position.norm() + setup.rest_offset[0].norm());
    velocity.add(to_double(kernels::xyz(v)), particles.velocity[0],
                 b.reference.velocity.norm() + b.reference.angular_velocity().norm() * setup.rest_offset[0].norm());
  }
}

}  // namespace
}  // namespace mssph::testing
