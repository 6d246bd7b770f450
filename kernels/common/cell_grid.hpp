#pragma once
// The neighbour grid of the kernels: cells of side h (the support radius), wrapped periodically
// onto 2^bx x 2^by x 2^bz cells, so cell (cx, cy, cz) has the key
//   (cx mod 2^bx) + 2^bx ((cy mod 2^by) + 2^by (cz mod 2^bz)).
// Every axis has at least 4 cells, so the 27 cells around a cell have 27 distinct keys and no
// particle is visited twice; particles of a distant periodic image share a key but fail the
// distance test. The grid needs no bounding box, never grows, and a particle flung far away
// costs nothing. Particles are sorted by key each step; cell k holds the sorted particles
// [cell_start[k], cell_end[k]).
#include "vec_math.hpp"

#include <cstdint>

namespace mssph::kernels {

inline constexpr std::uint32_t kEmptyCell = 0xffffffffu;

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

struct CellRanges {
  GridShape shape;
  const std::uint32_t* cell_start;  // kEmptyCell for an empty cell
  const std::uint32_t* cell_end;

  // Calls visit(s) for every sorted particle s in the 27 cells around x.
  template <class Visit>
  MSSPH_HD void for_each_candidate(Vec3 x, Visit&& visit) const {
    int cx, cy, cz;
    shape.cell_of(x, cx, cy, cz);
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const std::uint32_t k = shape.key(cx + dx, cy + dy, cz + dz);
          const std::uint32_t start = cell_start[k];
          if (start == kEmptyCell) continue;
          const std::uint32_t end = cell_end[k];
          for (std::uint32_t s = start; s < end; ++s) visit(s);
        }
      }
    }
  }
};

}  // namespace mssph::kernels
