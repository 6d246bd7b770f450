#pragma once
// The neighbour grid of the kernels: cells of side h (the support radius), wrapped periodically
// onto 2^bx x 2^by x 2^bz cells, so cell (cx, cy, cz) has the key
//   (cx mod 2^bx) + 2^bx ((cy mod 2^by) + 2^by (cz mod 2^bz)).
// Every axis has at least 4 cells, so the 27 cells around a cell have 27 distinct keys and no
// particle is visited twice; particles of a distant periodic image share a key but fail the
// distance test. The grid needs no bounding box, never grows, and a particle flung far away
// costs nothing. Particles are sorted by key each step.
#include "vec_math.hpp"

#include <cstdint>

namespace mssph::kernels {

struct GridShape {
  float inverse_cell_size = 0.0f;  // 1 / h
  std::uint32_t bits_x = 2, bits_y = 2, bits_z = 2;

  MSSPH_HD std::uint32_t cell_count() const { return 1u << (bits_x + bits_y + bits_z); }
  MSSPH_HD std::uint32_t total_bits() const { return bits_x + bits_y + bits_z; }

  // Integer cell coordinates of a position; clamped far beyond any scene so the conversion is
  // always defined (a runaway particle is caught by the blow-up check, not here).
  MSSPH_HD void cell_of(Vec3 x, int& cx, int& cy, int& cz) const {
    const float limit = 1.0e9f;
    cx = static_cast<int>(std::floor(std::fmin(std::fmax(x.x * inverse_cell_size, -limit), limit)));
    cy = static_cast<int>(std::floor(std::fmin(std::fmax(x.y * inverse_cell_size, -limit), limit)));
    cz = static_cast<int>(std::floor(std::fmin(std::fmax(x.z * inverse_cell_size, -limit), limit)));
  }
  MSSPH_HD std::uint32_t key(int cx, int cy, int cz) const {
    const std::uint32_t mx = (1u << bits_x) - 1u, my = (1u << bits_y) - 1u, mz = (1u << bits_z) - 1u;
    return (static_cast<std::uint32_t>(cx) & mx) | ((static_cast<std::uint32_t>(cy) & my) << bits_x) |
           ((static_cast<std::uint32_t>(cz) & mz) << (bits_x + bits_y));
  }
  MSSPH_HD std::uint32_t key_of(Vec3 x) const {
    int cx, cy, cz;
    cell_of(x, cx, cy, cz);
    return key(cx, cy, cz);
  }
};

// The index of the lowest set bit of a non-zero word.
MSSPH_HD std::uint32_t lowest_set_bit(std::uint32_t bits) {
#if defined(__CUDA_ARCH__)
  return static_cast<std::uint32_t>(__ffs(static_cast<int>(bits)) - 1);
#else
  return static_cast<std::uint32_t>(__builtin_ctz(bits));  // the .cu files' host side is C++17: no std::countr_zero
#endif
}

// The sorted particles of cell k are [cell_start[k], cell_start[k + 1]): cell_start holds, for
// every key, the first sorted particle whose key is not smaller (a prefix sum of the cell counts),
// so an empty cell is an empty range and the three cells of a row along x, whose keys are
// consecutive unless the row wraps, are one range.
struct CellRanges {
  GridShape shape;
  const std::uint32_t* cell_start;  // cell_count() + 1 entries

  // Calls visit_range(begin, end) for each contiguous range [begin, end) of sorted particles that
  // the 27 cells around x make: one per row of three cells along x, or one per cell where the row
  // wraps around the grid's x period.
  template <class VisitRange>
  MSSPH_HD void for_each_range(Vec3 x, VisitRange&& visit_range) const {
    int cx, cy, cz;
    shape.cell_of(x, cx, cy, cz);
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        const std::uint32_t first = shape.key(cx - 1, cy + dy, cz + dz);
        const std::uint32_t last = shape.key(cx + 1, cy + dy, cz + dz);
        if (last == first + 2) {
          visit_range(cell_start[first], cell_start[last + 1]);
        } else {  // the row wraps: three separate cells
          for (int dx = -1; dx <= 1; ++dx) {
            const std::uint32_t k = shape.key(cx + dx, cy + dy, cz + dz);
            visit_range(cell_start[k], cell_start[k + 1]);
          }
        }
      }
    }
  }

  // Calls visit(s) for every sorted particle s in the 27 cells around x that falls to `lane` of a
  // team of `lanes`: lane k takes candidates k, k + lanes, k + 2 lanes, ... of each contiguous
  // range. One lane alone (the host, large GPU scenes) visits every candidate; a team of lanes
  // splits the walk evenly, so a small scene keeps several independent loads in flight per
  // particle instead of one dependent walk of ~200 candidates.
  template <class Visit>
  MSSPH_HD void for_each_candidate(Vec3 x, std::uint32_t lane, std::uint32_t lanes, Visit&& visit) const {
    for_each_range(x, [&](std::uint32_t begin, std::uint32_t end) {
      for (std::uint32_t s = begin + lane; s < end; s += lanes) visit(s);
    });
  }

  // Calls visit(s) for every sorted particle s in the 27 cells around x that lies closer to x than
  // sqrt(radius2) (`position`: the sorted positions), in for_each_candidate's order. Each range is
  // taken 32 candidates at a time: their distances first, into a bit mask of the near ones, then a
  // visit of each near one. One lane per particle (large GPU scenes) is why: the lanes of a warp find
  // their ~30 neighbours among ~200 candidates each at other places, so a visit inside the walk
  // has the whole warp step through the pair arithmetic at nearly every candidate, some lane having
  // a neighbour there; the mask's visits run only as often as the lane with the most near ones in
  // the segment. The visits see exactly the candidates a filter on the same r^2 would pass.
  template <class Visit>
  MSSPH_HD void for_each_candidate_within(Vec3 x, float radius2, const Vec4* position, Visit&& visit) const {
    for_each_range(x, [&](std::uint32_t begin, std::uint32_t end) {
      for (std::uint32_t segment = begin; segment < end; segment += 32) {
        const std::uint32_t size = end - segment < 32 ? end - segment : 32;
        std::uint32_t near = 0;
        for (std::uint32_t k = 0; k < size; ++k) {
          if (squared_norm(x - xyz(position[segment + k])) < radius2) near |= 1u << k;
        }
        for (; near != 0; near &= near - 1) visit(segment + lowest_set_bit(near));
      }
    });
  }

  // Calls visit(s) for every sorted particle s in the 27 cells around x.
  template <class Visit>
  MSSPH_HD void for_each_candidate(Vec3 x, Visit&& visit) const {
    for_each_candidate(x, 0, 1, visit);
  }
};

}  // namespace mssph::kernels
