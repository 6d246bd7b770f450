#pragma once
// The float backends' checkpoint (Backend::save_state), the same arrays for `cpu` and `cuda`:
// canonical positions and velocities, the held or deactivated flags, the movable rigid bodies,
// the deformable particles' last rotations (the next step's rotation iteration starts from them:
// elastic_physics.hpp), the time and step count and, where the backend keeps neighbour lists
// (`cpu`, and `cuda` with teams of lanes), what makes a restart record the same lists. Everything
// else a step computes from these before reading it.
#include "backend/state_arrays.hpp"
#include "float_scene.hpp"

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
  // The neighbour lists, where the backend keeps them (list_skin.hpp): each particle's
  // canonical position at the last grid rebuild, from which a restart records the same lists
  // again, and whether the next step must rebuild. Empty and 0 otherwise.
  std::vector<Vec4> list_origin;
  std::uint8_t list_rebuild_requested = 0;
};

// The lists' origin in canonical order, for FloatRunState::list_origin: sorted particle s stood
// at sorted_origin[s] at the last rebuild, and is canonical particle sorted_id[s].
std::vector<Vec4> list_origin_in_canonical_order(const std::vector<Vec4>& sorted_origin,
                                                 const std::vector<std::uint32_t>& sorted_id);

StateArrays save_float_state(const FloatRunState& state);
// The state saved for `scene`: sizes are checked against it, and each rigid body keeps its
// particle range, mass and inertia from it (only what moves is restored). `with_lists`: the
// lists' arrays are read too (and required).
FloatRunState restore_float_state(const StateArrays& saved, const FloatScene& scene, bool with_lists);

}  // namespace mssph::kernels
