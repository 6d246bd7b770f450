#pragma once
// Neighbour lists: the candidates of the 27 cells (CellRanges) that lie within a radius of their
// particle, in the order the grid walk visits them. A sum visits a list's ~30-45 entries instead
// of the walk's ~200 candidates; since a candidate beyond the support adds nothing to either sum
// (add_density_pair, add_force_pair reject r^2 >= h^2 with the same arithmetic), a sum over the
// list takes the same terms in the same order as a sum over the walk: the same bits.
//
// One layout, written and read by two pairs of loops:
// - the host records one list per particle, of radius h + skin, when its grid is rebuilt
//   (record_neighbours; a rigid or deformable particle's own body left out), without a branch on
//   the distance (every candidate is written, the count advances only for one within the radius),
//   since on the host that branch is mispredicted about one candidate in six; on that step and the
//   following ones until the lists expire (list_skin.hpp) its density pass sums over each list
//   and copies its entries within h into a second list (density_sum_keeping_within, through
//   RowWriter), which its force pass reads (for_each_neighbour);
// - a GPU team's density pass, on a step that rebuilt the grid, records one list per lane, its
//   share of the walk, of radius h + skin, then sums over it (density_sum_recording, through
//   ListRecorder); the force pass visits it instead of walking the cells again, and so do both
//   passes of the steps until the next rebuild (for_each_listed; list_skin.hpp says when).
// The host's loops use that its rows are contiguous, the GPU's that a warp's lanes read together.
// Once a list is full its last entry takes every further candidate, so a list holds at most
// capacity - 1 entries; a list whose count reaches its capacity overflowed, and its reader
// falls back to the walk it was recorded from.
#include "particle_views.hpp"

#include <cstddef>

namespace mssph::kernels {

struct NeighbourLists {
  std::uint32_t capacity;      // entries per list
  std::uint32_t list_stride;   // from one list's first entry to the next list's
  std::uint32_t entry_stride;  // from a list's entry to its next
  std::uint32_t* count;        // per list; capacity or more: overflowed, walk the grid instead
  std::uint32_t* index;        // list l's entry k: index[l * list_stride + k * entry_stride], k < count[l]

  MSSPH_HD std::uint32_t* first_entry(std::uint32_t list) const {
    return index + static_cast<std::size_t>(list) * list_stride;
  }
};

// The host's lists, one per sorted particle, each a contiguous row: a particle's sums read it in order.
MSSPH_HD NeighbourLists particle_lists(std::uint32_t capacity, std::uint32_t* count, std::uint32_t* index) {
  return {capacity, capacity, 1, count, index};
}

// A GPU team's lists, one per lane of `lists` lanes in all: entry k of consecutive lanes are
// neighbours in memory, so a warp's lanes load their k-th entries together.
MSSPH_HD NeighbourLists lane_lists(std::uint32_t capacity, std::uint32_t lists, std::uint32_t* count,
                                   std::uint32_t* index) {
  return {capacity, 1, lists, count, index};
}

// Writes a GPU lane's list as its density pass meets the neighbours. It keeps a pointer to the
// next entry rather than an index: a warp runs the recording whenever one of its lanes meets a
// neighbour, nearly every candidate, so each instruction of it counts, and a pointer needs no
// 64-bit multiply by the stride.
class ListRecorder {
 public:
  MSSPH_HD ListRecorder(const NeighbourLists& lists, std::uint32_t list)
      : next_(lists.first_entry(list)), stride_(lists.entry_stride), last_(lists.capacity - 1) {}

  // Writes neighbour t at the next free entry (the last once full).
  MSSPH_HD void record(std::uint32_t t) {
    *next_ = t;
    next_ += count_ < last_ ? stride_ : 0u;
    ++count_;
  }
  MSSPH_HD std::uint32_t count() const { return count_; }

 private:
  std::uint32_t* next_;
  std::uint32_t stride_;
  std::uint32_t last_;
  std::uint32_t count_ = 0;
};

// Writes sorted particle s's row of the host's lists (particle_lists: entries contiguous, which
// this writer relies on to index the row without a stride) without a branch on whether an entry
// is kept: every entry offered is written, the count advances only for one kept (the last entry
// takes every entry once the row is full: overflowed).
class RowWriter {
 public:
  MSSPH_HD RowWriter(const NeighbourLists& lists, std::uint32_t s)
      : row_(lists.first_entry(s)), last_(lists.capacity - 1) {}

  MSSPH_HD void offer(std::uint32_t t, bool keep) {
    row_[count_ < last_ ? count_ : last_] = t;
    count_ += keep ? 1u : 0u;
  }
  MSSPH_HD std::uint32_t count() const { return count_; }

 private:
  std::uint32_t* row_;
  std::uint32_t last_;
  std::uint32_t count_ = 0;
};

// Records the candidates of the 27 cells closer than sqrt(radius2) to sorted particle s into its
// row of the host's lists, in the walk's order, but those of body `left_out` (s itself, at r = 0,
// is recorded unless it is of that body): a rigid or deformable particle's own body
// (body_left_out), whose pairs its sums skip, as the GPU teams' lists leave it out
// (density_sum_recording). Inside such a block a list is then empty, and the sums over it cost
// nothing.
MSSPH_HD void record_neighbours(const SortedView& v, const NeighbourLists& lists, std::uint32_t s, float radius2,
                                std::uint32_t left_out) {
  const Vec3 x_i = xyz(v.position[s]);
  RowWriter row(lists, s);
  v.grid.for_each_candidate(x_i, [&](std::uint32_t t) {
    const Vec4 p = v.position[t];
    row.offer(t, (squared_norm(x_i - xyz(p)) < radius2) & (body_of(p) != left_out));
  });
  lists.count[s] = row.count();
}

// Calls visit(t) for every entry of list `list` in its order; an overflowed list calls
// walk(visit) instead, the walk it was recorded from (whose out-of-support candidates add nothing
// to a sum). Entry k + 1 is loaded before entry k is visited, so that its load is in flight
// during the visit's own loads instead of after them: a small scene's lanes have few warps to
// hide those latencies behind.
template <class Walk, class Visit>
MSSPH_HD void for_each_listed(const NeighbourLists& lists, std::uint32_t list, Walk&& walk, Visit&& visit) {
  const std::uint32_t count = lists.count[list];
  if (count >= lists.capacity) {
    walk(visit);
    return;
  }
  const std::uint32_t* entry = lists.first_entry(list);
  std::uint32_t next = count > 0 ? *entry : 0u;
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::uint32_t t = next;
    entry += lists.entry_stride;
    if (k + 1 < count) next = *entry;
    visit(t);
  }
}

// Lane `lane` of `lanes`' share of the candidates around x as list `list` holds them (a GPU team's
// lists), as a candidate source: candidates(visit) calls visit(t) for each; an overflowed list
// walks the lane's share of the 27 cells around x, the walk it was recorded from.
MSSPH_HD auto listed_share(const CellRanges& grid, Vec3 x, std::uint32_t lane, std::uint32_t lanes,
                           const NeighbourLists& lists, std::uint32_t list) {
  return [&grid, x, lane, lanes, &lists, list](auto&& visit) {
    for_each_listed(
        lists, list, [&](auto&& all) { grid.for_each_candidate(x, lane, lanes, all); }, visit);
  };
}

// Calls visit(t) for every neighbour t of sorted particle s in the host's lists, in the grid
// walk's order: for_each_listed for a contiguous row, indexed directly instead of through a
// runtime stride.
template <class Visit>
MSSPH_HD void for_each_neighbour(const SortedView& v, const NeighbourLists& lists, std::uint32_t s, Visit&& visit) {
  const std::uint32_t count = lists.count[s];
  if (count >= lists.capacity) {
    v.grid.for_each_candidate(xyz(v.position[s]), visit);
    return;
  }
  const std::uint32_t* list = lists.first_entry(s);
  for (std::uint32_t k = 0; k < count; ++k) visit(list[k]);
}

// Sorted particle s's list as the candidate source of density_sum_over and force_sum_over.
MSSPH_HD auto neighbours_of(const SortedView& v, const NeighbourLists& lists, std::uint32_t s) {
  return [&v, &lists, s](auto&& visit) { for_each_neighbour(v, lists, s, visit); };
}

}  // namespace mssph::kernels
