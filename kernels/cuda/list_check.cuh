#pragma once
// The lists' check (list_skin.hpp) where the particles move: the force pass checks each particle it
// advances, the rigid-body pass each particle it places, against where the particle stood at the
// last rebuild. The next step's grid kernel then reads the verdict (ListRefreshState::moved_far)
// instead of checking every particle itself behind a grid-wide barrier. The same positions are
// checked against the same triggers as at the next step's start, so the same steps rebuild.
#include "../common/list_skin.hpp"
#include "device_state.cuh"

namespace mssph::kernels {

struct ListCheck {
  const Vec4* origin;         // canonical: each particle's position at the last rebuild
  const float* trigger2;      // per body (list_triggers2)
  ListRefreshState* refresh;  // null without lists: nothing is checked

  __device__ bool active() const { return refresh != nullptr; }

  // Called by every lane of a warp of an active check: `moves`, whether the lane's particle i of
  // body `body` now stands at `now`. Flags the next step's rebuild if one of them moved past its
  // trigger.
  __device__ void note(bool moves, std::uint32_t i, std::uint32_t body, Vec3 now) const {
    const bool far = moves && moved_past_trigger(now, xyz(origin[i]), trigger2[body]);
    if (__any_sync(0xffffffffu, far) && threadIdx.x % 32 == 0) atomicOr(&refresh->moved_far, 1u);
  }
};

inline ListCheck list_check(DeviceState& state) {
  if (state.list_refresh.size() == 0) return {nullptr, nullptr, nullptr};
  return {state.list_origin.data(), state.list_trigger2.data(), state.list_refresh.data()};
}

}  // namespace mssph::kernels
