#pragma once
// A stand-in for mssph::Backend, for the coupling cases and tests: one free rigid body (index 0)
// with isotropic inertia and no particles, so the haptic loop can be tested in milliseconds.
// Under a constant wrench over a step it moves exactly (x += v dt + F/(2m) dt^2; a fixed rotation axis turns by the
// mean angular velocity). An optional penalty floor stands in for the SPH interaction forces of a contact.
#include "backend/backend.hpp"
#include "util/pose.hpp"

#include <optional>
#include <stdexcept>

namespace mssph::test {

struct Floor {
  double height = 0.0;     // z of the surface [m]
  double stiffness = 0.0;  // [N/m]
  double damping = 0.0;    // [N s/m]
};

class RigidBodyDouble final : public Backend {
 public:
  RigidBodyDouble(double mass, double inertia, double dt) : mass_(mass), inertia_(inertia), dt_(dt) {}

  Pose pose;
  Twist twist;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  std::optional<Floor> floor;                                 // the body's centre of mass touches it
  std::size_t state_queries = 0;                              // rigid_body_state calls
  std::size_t wrench_updates = 0;                             // set_external_wrench calls
  Eigen::Vector3d applied_impulse = Eigen::Vector3d::Zero();  // sum of external force * dt [N s]

  BackendInfo info() const override { return {"rigid-body double", "host", "float64"}; }
  std::size_t particle_count() const override { return 0; }
  double time() const override { return static_cast<double>(steps_) * dt_; }

  void set_external_wrench(std::size_t body, const Eigen::Vector3d& force, const Eigen::Vector3d& torque) override {
    if (body != 0) throw std::invalid_argument("the double has one body");
    external_ = Wrench{force, torque};
    ++wrench_updates;
  }

  void step() override {
    interaction_ = contact();
    const Eigen::Vector3d force = external_.force + interaction_.force + mass_ * gravity;
    const Eigen::Vector3d acceleration = force / mass_;
    pose.position += twist.linear * dt_ + 0.5 * acceleration * dt_ * dt_;
    twist.linear += acceleration * dt_;
    const Eigen::Vector3d omega_start = twist.angular;
    twist.angular += (external_.torque + interaction_.torque) / inertia_ * dt_;
    pose.orientation = rotated(pose.orientation, 0.5 * (omega_start + twist.angular) * dt_);
    applied_impulse += external_.force * dt_;
    ++steps_;
  }

  std::vector<BodyState> body_states() override { return {state()}; }
  BodyState rigid_body_state(std::size_t body) override {
    if (body != 0) throw std::invalid_argument("the double has one body");
    ++state_queries;
    return state();
  }
  ParticleSnapshot snapshot() override { return {}; }
  std::vector<double> last_phase_seconds() const override { return std::vector<double>(kPhaseCount, 0.0); }
  ForceEvaluation evaluate_forces() override { return {}; }  // no particles
  void set_particle_positions(const std::vector<Eigen::Vector3d>&) override {}

  StateArrays save_state() override {
    StateArrays state;
    const Eigen::Quaterniond& q = pose.orientation;
    state.put("motion", std::vector<double>{pose.position.x(), pose.position.y(), pose.position.z(), q.x(), q.y(),
                                            q.z(), q.w(), twist.linear.x(), twist.linear.y(), twist.linear.z(),
                                            twist.angular.x(), twist.angular.y(), twist.angular.z()});
    state.put("external", std::vector<double>{external_.force.x(), external_.force.y(), external_.force.z(),
                                              external_.torque.x(), external_.torque.y(), external_.torque.z()});
    state.put_count("steps", static_cast<std::int64_t>(steps_));
    return state;
  }
  void restore_state(const StateArrays& state) override {
    const std::vector<double>& m = state.get<double>("motion", 13);
    pose.position = Eigen::Vector3d(&m[0]);
    pose.orientation = Eigen::Quaterniond(m[6], m[3], m[4], m[5]);
    twist.linear = Eigen::Vector3d(&m[7]);
    twist.angular = Eigen::Vector3d(&m[10]);
    const std::vector<double>& e = state.get<double>("external", 6);
    external_ = Wrench{Eigen::Vector3d(&e[0]), Eigen::Vector3d(&e[3])};
    steps_ = static_cast<std::size_t>(state.count("steps"));
  }

 private:
  Wrench contact() const {
    Wrench w;
    if (!floor) return w;
    const double depth = floor->height - pose.position.z();
    if (depth > 0.0) w.force.z() = floor->stiffness * depth - floor->damping * twist.linear.z();
    return w;
  }

  BodyState state() const {
    BodyState s;
    s.mass = mass_;
    s.centre_of_mass = pose.position;
    s.linear_momentum = mass_ * twist.linear;
    s.orientation = pose.orientation;
    s.angular_velocity = twist.angular;
    s.angular_momentum = inertia_ * twist.angular;
    s.interaction_force = interaction_.force;
    s.interaction_torque = interaction_.torque;
    return s;
  }

  double mass_;
  double inertia_;
  double dt_;
  std::size_t steps_ = 0;
  Wrench external_;
  Wrench interaction_;
};

}  // namespace mssph::test
