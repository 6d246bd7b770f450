// The reference backend's checkpoint (Backend::save_state): positions, velocities, deactivated
// particles, the movable rigid bodies and the time. Everything else a step computes from these
// (neighbours, densities, rotations, strains, forces) before reading it.
#include "reference_backend.hpp"

namespace mssph::reference {
namespace {

std::vector<double> flatten(const std::vector<Eigen::Vector3d>& vectors) {
  std::vector<double> out;
  out.reserve(3 * vectors.size());
  for (const Eigen::Vector3d& v : vectors) out.insert(out.end(), {v.x(), v.y(), v.z()});
  return out;
}

void unflatten(const std::vector<double>& values, std::vector<Eigen::Vector3d>& vectors) {
  for (std::size_t i = 0; i < vectors.size(); ++i) vectors[i] = Eigen::Vector3d(&values[3 * i]);
}

// The changing part of a rigid body, in this order; mass and inertia come from the setup.
constexpr std::size_t kRigidValues = 25;

void append(std::vector<double>& out, const Eigen::Vector3d& v) { out.insert(out.end(), {v.x(), v.y(), v.z()}); }

}  // namespace

StateArrays ReferenceBackend::save_state() {
  StateArrays state;
  state.put("position", flatten(particles_.position));
  state.put("velocity", flatten(particles_.velocity));
  state.put("left_domain", left_domain_);
  std::vector<double> rigid;
  for (const RigidBodyState& b : rigid_bodies_) {
    append(rigid, b.position);
    rigid.insert(rigid.end(), {b.orientation.x(), b.orientation.y(), b.orientation.z(), b.orientation.w()});
    for (const Eigen::Vector3d* v : {&b.velocity, &b.angular_momentum, &b.external_force, &b.external_torque,
                                     &b.interaction_force, &b.interaction_torque}) {
      append(rigid, *v);
    }
  }
  state.put("rigid_bodies", std::move(rigid));
  state.put_scalar("time", time_);
  return state;
}

void ReferenceBackend::restore_state(const StateArrays& state) {
  const std::size_t n = setup_.size();
  unflatten(state.get<double>("position", 3 * n), particles_.position);
  unflatten(state.get<double>("velocity", 3 * n), particles_.velocity);
  left_domain_ = state.get<std::uint8_t>("left_domain", n);
  const std::vector<double>& rigid = state.get<double>("rigid_bodies", kRigidValues * rigid_bodies_.size());
  const double* r = rigid.data();
  const auto next3 = [&r] {
    const Eigen::Vector3d v(r);
    r += 3;
    return v;
  };
  for (RigidBodyState& b : rigid_bodies_) {
    b.position = next3();
    b.orientation = Eigen::Quaterniond(r[3], r[0], r[1], r[2]);
    r += 4;
    for (Eigen::Vector3d* v : {&b.velocity, &b.angular_momentum, &b.external_force, &b.external_torque,
                               &b.interaction_force, &b.interaction_torque}) {
      *v = next3();
    }
  }
  time_ = state.scalar("time");
}

}  // namespace mssph::reference
