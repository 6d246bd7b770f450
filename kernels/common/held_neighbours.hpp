#pragma once
// A candidate source for the GPU's force sum in two stages: a lane walks its share of the 27
// cells' candidates (CellRanges::for_each_candidate), holds those within the support, and only
// then visits them. The CUDA force kernel's teams hold them in shared memory
// (cuda/held_neighbours.cuh); the host runs the same function in tests.
//
// Why: a warp runs a pair term whenever one of its 32 lanes meets a neighbour, and about one
// candidate in six is one, so a walk that visits as it goes pays the pair term at nearly every
// candidate (results/performance.md). Held first, the pair terms run together, once per held
// neighbour of the busiest lane. The neighbours are visited in the walk's order, and a candidate
// is held by the same r^2 < h^2 test (same arithmetic) that the pair terms apply to reject it, so a
// sum takes the same terms in the same order: the same bits as visiting every candidate.
#include "particle_views.hpp"

#include <cstdint>

namespace mssph::kernels {

// Where one lane holds its neighbours: entry k at first[k * stride], k < capacity.
struct HeldColumn {
  std::uint32_t* first;
  std::uint32_t stride;
  std::uint32_t capacity;
};

// Calls visit(t) for every candidate t within the support of x that falls to `lane` of a team of
// `lanes` (for_each_candidate's share), in its order. A lane that meets more neighbours than its
// column holds visits them each time the column fills.
template <class Visit>
MSSPH_HD void for_each_held_neighbour(const SortedView& v, Vec3 x, std::uint32_t lane, std::uint32_t lanes,
                                      HeldColumn held, Visit&& visit) {
  std::uint32_t count = 0;
  const auto visit_held = [&] {
    for (std::uint32_t k = 0; k < count; ++k) visit(held.first[k * held.stride]);
    count = 0;
  };
  v.grid.for_each_candidate(x, lane, lanes, [&](std::uint32_t t) {
    if (squared_norm(x - xyz(v.position[t])) >= v.step.smoothing.h2) return;
    held.first[count * held.stride] = t;
    if (++count == held.capacity) visit_held();
  });
  visit_held();
}

}  // namespace mssph::kernels
