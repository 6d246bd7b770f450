#pragma once
// The contact order's device side (contact_order.hpp): the density pass records each particle's
// ForceWalk and takes the places (record_force_walk).
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
    const bool asks = active && asks_contact_place(view.bodies[body_of(view.position[s])], near_other_body);
    const std::uint32_t lane = threadIdx.x % 32u;
    const std::uint32_t asking = __ballot_sync(0xffffffffu, asks);
    std::uint32_t first = 0;
    if (lane == 0 && asking != 0) first = atomicAdd(walks.contact_taken, __popc(asking));
    first = __shfl_sync(0xffffffffu, first, 0);
    if (asks) place = min(first + __popc(asking & ((1u << lane) - 1u)), walks.contact_capacity);
  }
  if (!active) return;
  if (place < walks.contact_capacity) walks.contact_order[place] = s;
  walks.walk[s] = force_walk_of(near_other_body, place, walks.contact_capacity);
}

}  // namespace mssph::kernels
