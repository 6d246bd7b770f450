#pragma once
// Per-particle neighbour lists of one step: the candidates of the 27 cells (CellRanges) that lie
// within the support h, in the order the grid walk visits them. The density and force sums visit a
// particle's ~30 neighbours instead of its ~200 candidates; since a candidate beyond the support
// adds nothing to either sum (add_density_pair, add_force_pair reject r^2 >= h^2 with the same
// arithmetic), a sum over the list takes the same terms in the same order as a sum over the walk:
// the same bits.
//
// A list is recorded without a branch on the distance (every candidate is written, the count
// advances only for one within the support), since on the host that branch is mispredicted about
// one candidate in six. The last entry takes every candidate once the list is full, so a list holds
// at most capacity - 1 neighbours; a particle with more keeps its count and falls back to the grid
// walk.
#include "particle_views.hpp"

namespace mssph::kernels {

struct NeighbourLists {
  std::uint32_t capacity;  // list entries per particle
  std::uint32_t* count;    // per sorted particle; capacity or more: overflowed, walk the grid instead
  std::uint32_t* index;    // sorted particle s's neighbours: index[s * capacity + k], k < count[s]
};

// Records sorted particle s's neighbours (itself included, r = 0) into its list.
MSSPH_HD void record_neighbours(const SortedView& v, const NeighbourLists& lists, std::uint32_t s) {
  const Vec3 x_i = xyz(v.position[s]);
  std::uint32_t* list = lists.index + static_cast<std::size_t>(s) * lists.capacity;
  const std::uint32_t last = lists.capacity - 1;
  std::uint32_t count = 0;
  v.grid.for_each_candidate(x_i, [&](std::uint32_t t) {
    list[count < last ? count : last] = t;
    count += squared_norm(x_i - xyz(v.position[t])) < v.step.smoothing.h2 ? 1u : 0u;
  });
  lists.count[s] = count;
}

// Calls visit(t) for every neighbour t of sorted particle s, in the grid walk's order; an
// overflowed list walks the grid itself (its out-of-support candidates add nothing to a sum).
template <class Visit>
MSSPH_HD void for_each_neighbour(const SortedView& v, const NeighbourLists& lists, std::uint32_t s, Visit&& visit) {
  const std::uint32_t count = lists.count[s];
  if (count >= lists.capacity) {
    v.grid.for_each_candidate(xyz(v.position[s]), visit);
    return;
  }
  const std::uint32_t* list = lists.index + static_cast<std::size_t>(s) * lists.capacity;
  for (std::uint32_t k = 0; k < count; ++k) visit(list[k]);
}

// Sorted particle s's list as the candidate source of density_sum_over and force_sum_over.
MSSPH_HD auto neighbours_of(const SortedView& v, const NeighbourLists& lists, std::uint32_t s) {
  return [&v, &lists, s](auto&& visit) { for_each_neighbour(v, lists, s, visit); };
}

}  // namespace mssph::kernels
