#pragma once
// A candidate source for the GPU's force sum in two stages: a lane walks its share of the 27
// cells' candidates (CellRanges::for_each_candidate), holds those within the support in shared
// memory, and only then visits them.
//
// Why: a warp runs a pair term whenever one of its 32 lanes meets a neighbour, and about one
// candidate in six is one, so a walk that visits as it goes pays the pair term at nearly every
// candidate (results/performance.md). Held first, the pair terms run together, once per held
// neighbour of the busiest lane. The neighbours are visited in the walk's order, and a candidate
// is held by the same r^2 < h^2 test (same arithmetic) that the pair terms apply to reject it, so a
// sum takes the same terms in the same order: the same bits as visiting every candidate.
#include "../common/particle_views.hpp"
#include "thread_blocks.cuh"

namespace mssph::kernels {

// This thread's column of its block's buffer of Capacity held neighbours: entry k at [k * kBlock].
// Column-major, so the threads of a warp hold their k-th neighbour in consecutive words and write
// and read distinct banks whatever their counts. One buffer per capacity, whichever sum uses it.
template <unsigned Capacity>
__device__ std::uint32_t* held_column() {
  __shared__ std::uint32_t held[Capacity * kBlock];
  return held + threadIdx.x;
}

// Calls visit(t) for every candidate t within the support of x that falls to `lane` of a team of
// `lanes` (for_each_candidate's share), in its order. Capacity neighbours are held per thread: a
// lane that meets more visits them each time its buffer fills. A thread runs one such walk at a
// time (the buffer is shared by all its walks of that capacity).
template <unsigned Capacity, class Visit>
__device__ void for_each_held_neighbour(const SortedView& v, Vec3 x, std::uint32_t lane, std::uint32_t lanes,
                                        Visit&& visit) {
  std::uint32_t* const held = held_column<Capacity>();
  std::uint32_t count = 0;
  const auto visit_held = [&] {
    for (std::uint32_t k = 0; k < count; ++k) visit(held[k * kBlock]);
    count = 0;
  };
  v.grid.for_each_candidate(x, lane, lanes, [&](std::uint32_t t) {
    if (squared_norm(x - xyz(v.position[t])) >= v.step.smoothing.h2) return;
    held[count * kBlock] = t;
    if (++count == Capacity) visit_held();
  });
  visit_held();
}

}  // namespace mssph::kernels
