#pragma once
// The contact order's device side (contact_order.hpp): the density pass records each particle's
// ForceWalk (record_force_walk), the force pass seats its teams by it (force_seat).
#include "../common/fluid_physics.hpp"
#include "contact_order.hpp"

#include <cstdint>

namespace mssph::kernels {

// Called by every lane of a warp, once particle s's density sums are in (`active`: its team's lane
// 0), with whether another body lies within h of it: records its ForceWalk. A walking rigid or
// deformable particle asks for the next place of the contact order, one atomic add a warp; which
// warp comes first varies from run to run, but a particle's force sums do not depend on where it
// is served, so the step's results do not either.
__device__ inline void record_force_walk(const ForceWalks& walks, const SortedView& view, std::uint32_t s, bool active,
                                         bool near_other_body) {
  std::uint32_t place = walks.contact_capacity;  // none
  if (walks.contact_capacity > 0) {
    const bool asks = active && near_other_body && takes_own_body_at_rest(view.bodies[body_of(view.position[s])]);
    const std::uint32_t lane = threadIdx.x % 32u;
    const std::uint32_t asking = __ballot_sync(0xffffffffu, asks);
    std::uint32_t first = 0;
    if (lane == 0 && asking != 0) first = atomicAdd(walks.contact_taken, __popc(asking));
    first = __shfl_sync(0xffffffffu, first, 0);
    if (asks) place = min(first + __popc(asking & ((1u << lane) - 1u)), walks.contact_capacity);
  }
  if (!active) return;
  const bool placed = place < walks.contact_capacity;
  if (placed) walks.contact_order[place] = s;
  walks.walk[s] = !near_other_body ? kNoWalk : placed ? kWalkInContactOrder : kWalkInCellOrder;
}

// The particle a force-pass team serves: team `member` below the particle count serves sorted
// particle `member` unless it holds a place in the contact order; the teams after them serve the
// places taken. `walks`: whether its force sums may be anything but zero (may_feel_forces).
struct ForceSeat {
  std::uint32_t s;
  bool active;
  bool walks;
};
__device__ inline ForceSeat force_seat(const SortedView& view, const ForceWalks& walks, std::uint32_t member) {
  const std::uint32_t n = view.step.particle_count;
  if (member < n) {
    const std::uint8_t walk = walks.walk[member];
    return {member, walk != kWalkInContactOrder,
            may_feel_forces(view.bodies[body_of(view.position[member])], walk != kNoWalk)};
  }
  const std::uint32_t place = member - n;
  if (place >= walks.contact_capacity || place >= *walks.contact_taken) return {0, false, false};
  return {walks.contact_order[place], true, true};
}

}  // namespace mssph::kernels
