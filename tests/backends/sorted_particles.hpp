#pragma once
// Particles sorted into the kernels' grid as the cpu backend sorts them (a stable counting sort by
// cell key, cell_start its prefix sum), for tests of the per-particle functions on the host.
#include "common/cell_grid.hpp"
#include "common/particle_views.hpp"
#include "common/vec_math.hpp"

#include <cstdint>
#include <random>
#include <vector>

namespace mssph::testing {

struct SortedParticles {
  kernels::GridShape shape;
  std::vector<std::uint32_t> cell_start;  // shape.cell_count() + 1 entries
  std::vector<kernels::Vec4> position;    // cell order; xyz [m], w = body index bits
  std::vector<std::uint16_t> cell_body;   // empty, or CellRanges::cell_body (note_cell_bodies)

  kernels::CellRanges grid() const {
    return kernels::CellRanges{shape, cell_start.data(), cell_body.empty() ? nullptr : cell_body.data()};
  }

  // Fills cell_body as the GPU's grid does, so that the walks of rigid and deformable particles
  // leave out their own body's rows; empty cells get `stale`, which no walk may read.
  void note_cell_bodies(std::uint16_t stale) {
    cell_body.assign(shape.cell_count(), stale);
    for (std::uint32_t k = 0; k < shape.cell_count(); ++k) {
      const std::uint32_t first = cell_start[k];
      if (cell_start[k + 1] == first) continue;
      cell_body[k] = kernels::cell_body_code(cell_start[k + 1] - first, [&](std::uint32_t m) {
        return kernels::index_from_float_bits(position[first + m].w);
      });
    }
  }
};

inline SortedParticles sort_into_grid(const std::vector<kernels::Vec4>& particles, kernels::GridShape shape) {
  SortedParticles sorted{shape, std::vector<std::uint32_t>(std::size_t{shape.cell_count()} + 1, 0u), {}, {}};
  std::vector<std::uint32_t> key(particles.size());
  for (std::size_t p = 0; p < particles.size(); ++p) key[p] = shape.key_of(kernels::xyz(particles[p]));
  for (const std::uint32_t k : key) ++sorted.cell_start[k + 1];
  for (std::size_t k = 1; k < sorted.cell_start.size(); ++k) sorted.cell_start[k] += sorted.cell_start[k - 1];
  std::vector<std::uint32_t> next(sorted.cell_start.begin(), sorted.cell_start.end() - 1);
  sorted.position.resize(particles.size());
  for (std::size_t p = 0; p < particles.size(); ++p) sorted.position[next[key[p]]++] = particles[p];
  return sorted;
}

// Grid-walk test particles: 2^3 x 2^2 x 2^2 cells of side 1 m, 300 particles spread over a 6 m cube (cells -3 to 3 on each
// axis: more than the grid's 4 along y and z, so distant particles share keys; across the period of
// 8 along x, so rows split there) and 400 packed into one cell, whose rows then hold many times 8
// candidates.
inline SortedParticles clustered_particles(std::mt19937_64& random) {
  std::uniform_real_distribution<float> spread(-2.5f, 3.5f), packed(0.05f, 0.95f);
  std::vector<kernels::Vec4> particles;
  for (int p = 0; p < 300; ++p) particles.push_back(kernels::Vec4{spread(random), spread(random), spread(random), 0.0f});
  for (int p = 0; p < 400; ++p) particles.push_back(kernels::Vec4{packed(random), packed(random), packed(random), 0.0f});
  kernels::GridShape shape;
  shape.inverse_cell_size = 1.0f;
  shape.bits_x = 3;
  return sort_into_grid(particles, shape);
}

}  // namespace mssph::testing
