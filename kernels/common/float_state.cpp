#include "float_state.hpp"

#include <cstring>
#include <type_traits>

namespace mssph::kernels {
namespace {

// Records made of floats only (Vec4, Quat, Vec3) as a flat float array, bit for bit.
template <class Record>
std::vector<float> as_floats(const std::vector<Record>& records) {
  static_assert(std::is_trivially_copyable_v<Record> && sizeof(Record) % sizeof(float) == 0);
  std::vector<float> out(records.size() * (sizeof(Record) / sizeof(float)));
  if (!records.empty()) std::memcpy(out.data(), records.data(), records.size() * sizeof(Record));
  return out;
}

template <class Record>
std::vector<Record> from_floats(const std::vector<float>& values) {
  std::vector<Record> out(values.size() / (sizeof(Record) / sizeof(float)));
  if (!out.empty()) std::memcpy(out.data(), values.data(), out.size() * sizeof(Record));
  return out;
}

constexpr std::size_t kFloatsPerVec4 = sizeof(Vec4) / sizeof(float);

// The moving part of a rigid body, in this order.
struct RigidMotion {
  Vec3 position, position_carry;
  Quat orientation;
  Vec3 velocity, angular_momentum, external_force, external_torque, interaction_force, interaction_torque;
};
constexpr std::size_t kFloatsPerRigidBody = sizeof(RigidMotion) / sizeof(float);

}  // namespace

std::vector<Vec4> list_origin_in_canonical_order(const std::vector<Vec4>& sorted_origin,
                                                 const std::vector<std::uint32_t>& sorted_id) {
  std::vector<Vec4> origin(sorted_origin.size(), Vec4{0, 0, 0, 0});
  for (std::size_t s = 0; s < sorted_origin.size(); ++s) origin[sorted_id[s]] = make_vec4(xyz(sorted_origin[s]), 0.0f);
  return origin;
}

StateArrays save_float_state(const FloatRunState& state) {
  StateArrays out;
  out.put("position", as_floats(state.position));
  out.put("velocity", as_floats(state.velocity));
  out.put("fixed", state.fixed);
  std::vector<RigidMotion> motion;
  for (const RigidBody& b : state.rigid_bodies) {
    motion.push_back({b.position, b.position_carry, b.orientation, b.velocity, b.angular_momentum, b.external_force,
                      b.external_torque, b.interaction_force, b.interaction_torque});
  }
  out.put("rigid_bodies", as_floats(motion));
  out.put("rotation", as_floats(state.rotation));
  out.put_scalar("time", state.time);
  out.put_count("steps", static_cast<std::int64_t>(state.steps));
  if (!state.list_origin.empty()) {
    out.put("list_origin", as_floats(state.list_origin));
    out.put("list_rebuild_requested", std::vector<std::uint8_t>{state.list_rebuild_requested});
  }
  return out;
}

FloatRunState restore_float_state(const StateArrays& saved, const FloatScene& scene, bool with_lists) {
  const std::size_t n = scene.position.size();
  FloatRunState state;
  state.position = from_floats<Vec4>(saved.get<float>("position", kFloatsPerVec4 * n));
  state.velocity = from_floats<Vec4>(saved.get<float>("velocity", kFloatsPerVec4 * n));
  state.fixed = saved.get<std::uint8_t>("fixed", n);
  const std::vector<RigidMotion> motion =
      from_floats<RigidMotion>(saved.get<float>("rigid_bodies", kFloatsPerRigidBody * scene.rigid_bodies.size()));
  state.rigid_bodies = scene.rigid_bodies;
  for (std::size_t b = 0; b < motion.size(); ++b) {
    RigidBody& body = state.rigid_bodies[b];
    const RigidMotion& m = motion[b];
    body.position = m.position;
    body.position_carry = m.position_carry;
    body.orientation = m.orientation;
    body.velocity = m.velocity;
    body.angular_momentum = m.angular_momentum;
    body.external_force = m.external_force;
    body.external_torque = m.external_torque;
    body.interaction_force = m.interaction_force;
    body.interaction_torque = m.interaction_torque;
  }
  state.rotation = from_floats<Quat>(saved.get<float>("rotation", 4 * scene.deformable_body.size()));
  state.time = saved.scalar("time");
  state.steps = static_cast<std::uint64_t>(saved.count("steps"));
  if (with_lists) {
    state.list_origin = from_floats<Vec4>(saved.get<float>("list_origin", kFloatsPerVec4 * n));
    state.list_rebuild_requested = saved.get<std::uint8_t>("list_rebuild_requested", 1).front();
  }
  return state;
}

}  // namespace mssph::kernels
