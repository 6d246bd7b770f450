#pragma once
// With lists, the next step's particles in cell order, written where they move. The grid's cell
// order holds from one rebuild to the next, so the force pass writes each particle it serves at
// its place s, advanced or as it was, and the rigid placement each particle it places at
// place_of[i]: the arrays the next step reads, with the same bits the grid kernel's copy
// (place_in_cell_order) would give them. The step reads one pair of arrays and writes the other,
// and the two trade places after it (cuda_backend.cu), so a list step launches no copy.
#include "../common/fluid_physics.hpp"
#include "device_state.cuh"

namespace mssph::kernels {

struct NextCellOrder {
  Vec4* position;  // null without lists: nothing is written
  Vec4* velocity;
  const std::uint32_t* place_of;  // canonical index -> place; null without rigid bodies

  __device__ bool active() const { return position != nullptr; }

  // Particle of body `body` at place s, standing at x with its canonical velocity after this step.
  __device__ void put(std::uint32_t s, std::uint32_t body, Vec3 x, const Vec4& canonical_velocity) const {
    position[s] = cell_ordered_position(x, body);
    velocity[s] = canonical_velocity;
  }
};

inline NextCellOrder next_cell_order(DeviceState& state) {
  return {state.next_sorted_position.data(), state.next_sorted_velocity.data(), state.place_of.data()};
}

}  // namespace mssph::kernels
