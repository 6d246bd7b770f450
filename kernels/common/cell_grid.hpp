#pragma once
// The neighbour grid of the kernels: cells of side h (the support radius), wrapped periodically
// onto 2^bx x 2^by x 2^bz cells, so cell (cx, cy, cz) has the key
//   ((cx + ox) mod 2^bx) + 2^bx ((cy mod 2^by) + 2^by (cz mod 2^bz)),
// ox shifting the wrap along x out of the scene (GridShape::origin_x).
// Every axis has at least 4 cells, so the 27 cells around a cell have 27 distinct keys and no
// particle is visited twice; particles of a distant periodic image share a key but fail the
// distance test. The grid needs no bounding box, never grows, and a particle flung far away
// costs nothing. Particles are sorted by key at each rebuild, each cell's lower half along x
// first (CellRanges::cell_middle).
#include "vec_math.hpp"

#include <cstdint>

namespace mssph::kernels {

struct GridShape {
  float inverse_cell_size = 0.0f;  // 1 / h
  std::uint32_t bits_x = 2, bits_y = 2, bits_z = 2;
  // Added to a cell's x coordinate before it wraps (modulo 2^32, so a negative shift is its two's
  // complement). A row of three cells along x is one range of sorted particles unless it wraps
  // (CellRanges::for_each_range); a wrapped row is walked as three cells, more slowly, and a
  // warp whose lanes take both kinds of rows runs both. choose_grid_shape puts the wrap beside the
  // scene, so that no row inside it wraps (at 0, a scene centred on the origin would wrap there).
  std::uint32_t origin_x = 0;

  MSSPH_HD std::uint32_t cell_count() const { return 1u << (bits_x + bits_y + bits_z); }
  MSSPH_HD std::uint32_t total_bits() const { return bits_x + bits_y + bits_z; }

  // A coordinate in cells; clamped far beyond any scene so the conversion to int is always defined
  // (a runaway particle is caught by the blow-up check, not here).
  MSSPH_HD float in_cells(float coordinate) const {
    const float limit = 1.0e9f;
    return std::fmin(std::fmax(coordinate * inverse_cell_size, -limit), limit);
  }
  // Integer cell coordinates of a position.
  MSSPH_HD void cell_of(Vec3 x, int& cx, int& cy, int& cz) const {
    cx = static_cast<int>(std::floor(in_cells(x.x)));
    cy = static_cast<int>(std::floor(in_cells(x.y)));
    cz = static_cast<int>(std::floor(in_cells(x.z)));
  }
  // Where x lies within its cell along x, as a fraction of the cell in [0, 1).
  MSSPH_HD float x_fraction(Vec3 x) const {
    const float c = in_cells(x.x);
    return c - std::floor(c);
  }
  // Whether x lies in the upper half of its cell along x: the grids (GPU and host) sort each cell's
  // particles of the lower half first (CellRanges::cell_middle).
  MSSPH_HD bool in_upper_half(Vec3 x) const { return x_fraction(x) >= 0.5f; }
  MSSPH_HD std::uint32_t key(int cx, int cy, int cz) const {
    const std::uint32_t mx = (1u << bits_x) - 1u, my = (1u << bits_y) - 1u, mz = (1u << bits_z) - 1u;
    return ((static_cast<std::uint32_t>(cx) + origin_x) & mx) | ((static_cast<std::uint32_t>(cy) & my) << bits_x) |
           ((static_cast<std::uint32_t>(cz) & mz) << (bits_x + bits_y));
  }
  MSSPH_HD std::uint32_t key_of(Vec3 x) const {
    int cx, cy, cz;
    cell_of(x, cx, cy, cz);
    return key(cx, cy, cz);
  }
  // A particle's half key, by which the grids (GPU and host) sort: its cell key times two, plus
  // one in the cell's upper half along x (in_upper_half). Cell keys take at most 31 bits below
  // 2^30 particles (choose_grid_shape: about two cells per particle), whose arrays alone would
  // take 120 GB.
  MSSPH_HD std::uint32_t half_key_of(Vec3 x) const { return key_of(x) << 1 | (in_upper_half(x) ? 1u : 0u); }
};

// The index of the lowest set bit of a non-zero word.
MSSPH_HD std::uint32_t lowest_set_bit(std::uint32_t bits) {
#if defined(__CUDA_ARCH__)
  return static_cast<std::uint32_t>(__ffs(static_cast<int>(bits)) - 1);
#else
  return static_cast<std::uint32_t>(__builtin_ctz(bits));  // the .cu files' host side is C++17: no std::countr_zero
#endif
}

// Where a one-lane walk keeps the segments of candidates it found near
// (CellRanges::for_each_candidate_within): segment k's first sorted particle and the bit mask of
// its near candidates (bit b: particle first + b), for k below `capacity`. The GPU's force kernel
// keeps them in shared memory, a column per thread; elsewhere this array does.
template <std::uint32_t Capacity>
struct HeldSegments {
  static_assert(Capacity > 0, "a walk holds at least one segment");
  static constexpr std::uint32_t capacity = Capacity;
  std::uint32_t first_[Capacity];
  std::uint32_t near_[Capacity];

  MSSPH_HD void put(std::uint32_t k, std::uint32_t first, std::uint32_t near) {
    first_[k] = first;
    near_[k] = near;
  }
  MSSPH_HD std::uint32_t first(std::uint32_t k) const { return first_[k]; }
  MSSPH_HD std::uint32_t near(std::uint32_t k) const { return near_[k]; }
};

// Calls visit(first + b) for each set bit b of each of the first `count` held segments, in order:
// one loop whose every turn visits one candidate, taking the next segment first when the last is
// done (no segment is held empty), so a warp's lanes turn it together as often as the lane with
// the most candidates needs.
template <class Held, class Visit>
MSSPH_HD void visit_held(const Held& held, std::uint32_t count, Visit&& visit) {
  std::uint32_t next = 0, first = 0, near = 0;
  for (;;) {
    if (near == 0) {
      if (next == count) return;
      first = held.first(next);
      near = held.near(next);
      ++next;
    }
    visit(first + lowest_set_bit(near));
    near &= near - 1;
  }
}

// No body: a walk that leaves no cells out (CellRanges).
inline constexpr std::uint32_t kNoBody = 0xffffffffu;
// A cell_body entry: the cell's particles belong to more than one body, or to one whose index
// does not fit 16 bits.
inline constexpr std::uint16_t kMixedCell = 0xffffu;

// The cell_body entry of a cell whose particles all belong to `body`: its index, or kMixedCell
// where that does not fit 16 bits.
MSSPH_HD std::uint16_t sole_body_entry(std::uint32_t body) {
  return body < kMixedCell ? static_cast<std::uint16_t>(body) : kMixedCell;
}
// A cell's entry, so far `entry`, once a particle of `body` joins it: unchanged where that is the
// body it names, else kMixedCell. A non-empty cell's entry is its first particle's sole_body_entry
// joined by each of the others; the GPU's grid kernel writes it in two stages, the first
// particle's and then every other's where it differs (kernels/cuda/neighbour_grid.cu).
MSSPH_HD std::uint16_t entry_joined_by(std::uint16_t entry, std::uint32_t body) {
  return sole_body_entry(body) == entry ? entry : kMixedCell;
}

// A walk from a point that lies above the middle of its cell along x by more than this fraction
// of a cell trims the lower half of the cell below along x (CellRanges::cell_middle), and the
// other way round. The margin covers the float rounding of the two fractions, the point's and a
// trimmed particle's (each within ~6e-8 of its coordinate in cells), so every trimmed particle lies
// farther than one cell from the point: for coordinates within 1e5 cells of the origin, beyond
// which float positions resolve no better than a hundredth of a cell anyway.
inline constexpr float kHalfTrimMargin = 1.0f / 64.0f;

// The bit mask of the `size` (1 to 32) sorted particles from `first` that lie closer to x than
// sqrt(radius2): bit b for particle first + b. Addressed from the first by a signed offset, whose
// overflow the compiler may assume away, so the unrolled loads take their offsets as immediates
// (an unsigned index, which may wrap, costs each candidate its own address sums). Each candidate's
// bit enters at the top and the mask moves down one place, as the density walk's notes are built
// (density_sum_noting_near); the last shift puts candidate b's at bit b.
MSSPH_HD std::uint32_t near_mask(Vec3 x, float radius2, const Vec4* position, std::uint32_t first, int size) {
  const Vec4* candidate = position + first;
  std::uint32_t near = 0;
  for (int k = 0; k < size; ++k) {
    near = near >> 1 | (squared_norm(x - xyz(candidate[k])) < radius2 ? 0x80000000u : 0u);
  }
  return near >> (32 - size);
}

// The sorted particles of cell k are [cell_start[k], cell_start[k + 1]): cell_start holds, for
// every key, the first sorted particle whose key is not smaller (a prefix sum of the cell counts),
// so an empty cell is an empty range and the three cells of a row along x, whose keys are
// consecutive unless the row wraps, are one range.
struct CellRanges {
  GridShape shape;
  const std::uint32_t* cell_start;  // cell_count() + 1 entries
  // For each non-empty cell, the body all its particles belong to, else kMixedCell (empty cells'
  // entries are stale): lets a walk leave out the rows of cells that hold nothing but one body.
  // Null where no walk does (scenes of fluid alone, the host).
  const std::uint16_t* cell_body = nullptr;
  // Where the grids (GPU and host) split each cell along x (GridShape::in_upper_half): cell k's
  // particles of the lower half are [cell_start[k], cell_middle[k]), of the upper half
  // [cell_middle[k], cell_start[k + 1]). A one-lane walk from the upper half of a cell (trimmed_side)
  // skips the lower half of the cell below it along x, whose particles all lie farther than a cell
  // away, and the other way round: it walks 2.5 cells of each row instead of 3. Null where cells are
  // not split (tests of whole cells).
  const std::uint32_t* cell_middle = nullptr;

  // +1 where x lies above the middle of its cell along x by kHalfTrimMargin, -1 below it by as
  // much, else 0 (also where cells are not split): which side a walk from x trims.
  MSSPH_HD int trimmed_side(Vec3 x) const {
    if (cell_middle == nullptr) return 0;
    const float fraction = shape.x_fraction(x);
    return fraction >= 0.5f + kHalfTrimMargin ? 1 : fraction < 0.5f - kHalfTrimMargin ? -1 : 0;
  }
  // Where a walk from side `side` begins cell k, the cell below it along x; where it ends cell k,
  // the cell above.
  MSSPH_HD std::uint32_t begin_below(std::uint32_t k, int side) const {
    return side > 0 ? cell_middle[k] : cell_start[k];
  }
  MSSPH_HD std::uint32_t end_above(std::uint32_t k, int side) const {
    return side < 0 ? cell_middle[k] : cell_start[k + 1];
  }

  // Whether a walk can leave out cells that hold nothing but body `body`: not where cell_body is
  // null, nor for kNoBody or any index an entry cannot name (it would read kMixedCell as its own).
  MSSPH_HD bool may_leave_out(std::uint32_t body) const { return cell_body != nullptr && body < kMixedCell; }

  // The cells of the 27 around x that hold no particle of a body other than `body` (empty ones
  // included), as a mask: bit cell_bit(dx, dy, dz) for the cell at offset (dx, dy, dz) from x's.
  // Only cells cell_bit = share, share + shares, ... are checked, the others' bits are clear:
  // lanes that share a cell and a body split the 27 checks and join their masks
  // (kernels/cuda/warp_cell_checks.cuh).
  // 0 where no cell can be left out (may_leave_out).
  MSSPH_HD std::uint32_t cells_holding_only(Vec3 x, std::uint32_t body, std::uint32_t share = 0,
                                            std::uint32_t shares = 1) const {
    if (!may_leave_out(body)) return 0;
    int cx, cy, cz;
    shape.cell_of(x, cx, cy, cz);
    std::uint32_t cells = 0;
    for (std::uint32_t bit = share; bit < 27; bit += shares) {
      const int dx = static_cast<int>(bit % 3) - 1;  // bit = cell_bit(dx, dy, dz)
      const int dy = static_cast<int>(bit / 3 % 3) - 1;
      const int dz = static_cast<int>(bit / 9) - 1;
      const std::uint32_t k = shape.key(cx + dx, cy + dy, cz + dz);
      if (cell_start[k] == cell_start[k + 1] || cell_body[k] == body) cells |= 1u << bit;
    }
    return cells;
  }
  // The bit of the cell at offset (dx, dy, dz) in a mask of the 27 cells around a point.
  MSSPH_HD static std::uint32_t cell_bit(int dx, int dy, int dz) {
    return static_cast<std::uint32_t>(9 * (dz + 1) + 3 * (dy + 1) + dx + 1);
  }

  // Calls visit_range(begin, end) for each contiguous range [begin, end) of sorted particles that
  // the 27 cells around x make, less the halves the walk trims if `trim_halves` (cell_middle): one
  // per row of three cells along x, or one per cell where the row wraps around the grid's x
  // period. A row whose three cells (or a wrapped cell) are all in the mask `cells_left_out`
  // (cells_holding_only) is not visited: the density walks of rigid and deformable particles leave
  // out those that hold nothing but their own body, whose pairs add nothing to their sums
  // (fluid_physics.hpp, body_left_out), and which make up every row inside a large block.
  template <class VisitRange>
  MSSPH_HD void for_each_range(Vec3 x, VisitRange&& visit_range, std::uint32_t cells_left_out = 0,
                               bool trim_halves = true) const {
    int cx, cy, cz;
    shape.cell_of(x, cx, cy, cz);
    const int side = trim_halves ? trimmed_side(x) : 0;
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        const std::uint32_t first = shape.key(cx - 1, cy + dy, cz + dz);
        const std::uint32_t last = shape.key(cx + 1, cy + dy, cz + dz);
        const std::uint32_t row_left_out = cells_left_out >> cell_bit(-1, dy, dz) & 7u;
        if (last == first + 2) {
          if (row_left_out != 7u) visit_range(begin_below(first, side), end_above(last, side));
        } else {  // the row wraps: three separate cells
          for (int dx = -1; dx <= 1; ++dx) {
            const std::uint32_t k = shape.key(cx + dx, cy + dy, cz + dz);
            if ((row_left_out >> (dx + 1) & 1u) == 0) {
              visit_range(dx < 0 ? begin_below(k, side) : cell_start[k],
                          dx > 0 ? end_above(k, side) : cell_start[k + 1]);
            }
          }
        }
      }
    }
  }

  // Calls visit(s) for every sorted particle s in the 27 cells around x (but the rows for_each_range
  // leaves out) that falls to `lane` of a team of `lanes`: lane k takes candidates k, k + lanes,
  // k + 2 lanes, ... of each contiguous range. One lane alone (the host, large GPU scenes) visits
  // every candidate; a team of lanes splits the walk evenly, so a small scene keeps several
  // independent loads in flight per particle instead of one dependent walk of ~200 candidates.
  // One lane trims split cells' halves; a team walks whole cells: its walks run only on the steps
  // that rebuild the grid (list_skin.hpp), and the trim's registers would cost its density kernel
  // blocks on every step (step_kernels.cu).
  template <class Visit>
  MSSPH_HD void for_each_candidate(Vec3 x, std::uint32_t lane, std::uint32_t lanes, Visit&& visit,
                                   std::uint32_t cells_left_out = 0) const {
    for_each_range(
        x,
        [&](std::uint32_t begin, std::uint32_t end) {
          for (std::uint32_t s = begin + lane; s < end; s += lanes) visit(s);
        },
        cells_left_out, /*trim_halves=*/lanes == 1);
  }

  // Calls visit_segment(first, size) for each segment of for_each_range's ranges (one lane's: halves
  // trimmed, nothing left out), in order: runs of `size` sorted particles from `first`, 32 of them
  // but at a range's end. A one-lane walk takes a segment's near candidates as one bit mask
  // (near_mask).
  template <class VisitSegment>
  MSSPH_HD void for_each_segment(Vec3 x, VisitSegment&& visit_segment) const {
    for_each_range(x, [&](std::uint32_t begin, std::uint32_t end) {
      for (std::uint32_t segment = begin; segment < end; segment += 32) {
        visit_segment(segment, end - segment < 32 ? static_cast<int>(end - segment) : 32);
      }
    });
  }

  // Calls visit(s) for every sorted particle s in the 27 cells around x that lies closer to x than
  // sqrt(radius2) (`position`: the sorted positions), in for_each_candidate's order, after the
  // walk rather than inside it. The walk takes each segment's distances into a bit mask of the
  // near ones (for_each_segment, near_mask), and keeps each segment that has one in `held`
  // (HeldSegments); then one loop visits the held segments' near candidates in order. The lanes of
  // a warp (one lane per particle, large GPU scenes) find their ~30 neighbours among ~200
  // candidates each at other places: visits inside the walk would leave most lanes idle, while one
  // loop after the walk runs only as often as the lane with the most neighbours needs. A walk that
  // finds more segments than `held` holds visits those it holds and starts again. The visits see
  // exactly the candidates a filter on the same r^2 would pass.
  template <class Held, class Visit>
  MSSPH_HD void for_each_candidate_within(Vec3 x, float radius2, const Vec4* position, Held& held,
                                          Visit&& visit) const {
    for_each_candidate_near(
        x, [&](std::uint32_t, std::uint32_t first, int size) { return near_mask(x, radius2, position, first, size); },
        held, visit);
  }

  // The same walk with the masks from near_of(k, first, size) for the k-th segment (counted from
  // 0 in for_each_segment's order): a GPU force walk takes those its density walk noted
  // (near_notes.hpp).
  template <class NearOf, class Held, class Visit>
  MSSPH_HD void for_each_candidate_near(Vec3 x, NearOf&& near_of, Held& held, Visit&& visit) const {
    std::uint32_t count = 0, k = 0;
    for_each_segment(x, [&](std::uint32_t first, int size) {
      const std::uint32_t near = near_of(k++, first, size);
      if (near == 0) return;
      if (count == Held::capacity) {
        visit_held(held, count, visit);
        count = 0;
      }
      held.put(count++, first, near);
    });
    visit_held(held, count, visit);
  }

  // Calls visit(s) for every sorted particle s in the 27 cells around x.
  template <class Visit>
  MSSPH_HD void for_each_candidate(Vec3 x, Visit&& visit) const {
    for_each_candidate(x, 0, 1, visit);
  }
};

}  // namespace mssph::kernels
