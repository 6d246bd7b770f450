#pragma once
// The float backends' checkpoint (Backend::save_state), the same arrays for `cpu` and `cuda`:
// canonical positions and velocities, the held or deactivated flags, the movable rigid bodies,
// the deformable particles' last rotations (the next step's rotation iteration starts from them:
// elastic_physics.hpp) and the time and step count. Everything else a step computes from these
// before reading it.
#include "float_scene.hpp"
#include "sim/state_arrays.hpp"

#include <cstdint>
#include <vector>

namespace mssph::kernels {

struct FloatRunState {
  std::vector<Vec4> position, velocity;  // canonical order, kernels' frame
  std::vector<std::uint8_t> fixed;
  std::vector<RigidBody> rigid_bodies;
  std::vector<Quat> rotation;  // per deformable particle
  double time = 0.0;
  std::uint64_t steps = 0;
};

StateArrays save_float_state(const FloatRunState& state);
// The state saved for `scene`: sizes are checked against it, and each rigid body keeps its
// particle range, mass and inertia from it (only what moves is restored).
FloatRunState restore_float_state(const StateArrays& saved, const FloatScene& scene);

}  // namespace mssph::kernels
