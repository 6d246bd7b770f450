#pragma once
// Particles sorted into the kernels' grid as the cpu backend sorts them (a stable counting sort by
// cell key, cell_start its prefix sum), for tests of the per-particle functions on the host.
#include "common/cell_grid.hpp"
#include "common/vec_math.hpp"

#include <cstdint>
#include <vector>

namespace mssph::testing {

struct SortedParticles {
  kernels::GridShape shape;
  std::vector<std::uint32_t> cell_start;  // shape.cell_count() + 1 entries
  std::vector<kernels::Vec4> position;    // cell order; xyz [m], w = body index bits

  kernels::CellRanges grid() const { return kernels::CellRanges{shape, cell_start.data()}; }
};

inline SortedParticles sort_into_grid(const std::vector<kernels::Vec4>& particles, kernels::GridShape shape) {
  SortedParticles sorted{shape, std::vector<std::uint32_t>(std::size_t{shape.cell_count()} + 1, 0u), {}};
  std::vector<std::uint32_t> key(particles.size());
  for (std::size_t p = 0; p < particles.size(); ++p) key[p] = shape.key_of(kernels::xyz(particles[p]));
  for (const std::uint32_t k : key) ++sorted.cell_start[k + 1];
  for (std::size_t k = 1; k < sorted.cell_start.size(); ++k) sorted.cell_start[k] += sorted.cell_start[k - 1];
  std::vector<std::uint32_t> next(sorted.cell_start.begin(), sorted.cell_start.end() - 1);
  sorted.position.resize(particles.size());
  for (std::size_t p = 0; p < particles.size(); ++p) sorted.position[next[key[p]]++] = particles[p];
  return sorted;
}

}  // namespace mssph::testing
