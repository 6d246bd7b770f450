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

// The cell_body entry of a non-empty cell of `count` particles whose bodies are body_of(0), ...,
// body_of(count - 1), in one pass on the host: the first one's sole_body_entry joined by each of
// the others in turn (kernels/common/cell_grid.hpp, entry_joined_by).
template <class BodyOf>
std::uint16_t cell_body_code(std::uint32_t count, BodyOf&& body_of) {
  std::uint16_t entry = kernels::sole_body_entry(body_of(0u));
  for (std::uint32_t k = 1; k < count; ++k) entry = kernels::entry_joined_by(entry, body_of(k));
  return entry;
}

struct SortedParticles {
  kernels::GridShape shape;
  std::vector<std::uint32_t> cell_start;   // shape.cell_count() + 1 entries
  std::vector<kernels::Vec4> position;     // cell order; xyz [m], w = body index bits
  std::vector<std::uint16_t> cell_body;    // empty, or CellRanges::cell_body (note_cell_bodies)
  std::vector<std::uint32_t> cell_middle;  // empty, or CellRanges::cell_middle (sort_into_half_cells)

  kernels::CellRanges grid() const {
    return kernels::CellRanges{shape, cell_start.data(), cell_body.empty() ? nullptr : cell_body.data(),
                               cell_middle.empty() ? nullptr : cell_middle.data()};
  }

  // Fills cell_body as the GPU's grid does, so that the walks of rigid and deformable particles
  // leave out their own body's rows; empty cells get `stale`, which no walk may read.
  void note_cell_bodies(std::uint16_t stale) {
    cell_body.assign(shape.cell_count(), stale);
    for (std::uint32_t k = 0; k < shape.cell_count(); ++k) {
      const std::uint32_t first = cell_start[k];
      if (cell_start[k + 1] == first) continue;
      cell_body[k] = cell_body_code(cell_start[k + 1] - first, [&](std::uint32_t m) {
        return kernels::index_from_float_bits(position[first + m].w);
      });
    }
  }
};

// A grid of cells of side 1 m, 2^bits_x x 2^bits_y x 2^bits_z of them, the wrap along x shifted by
// origin_x cells (GridShape::origin_x).
inline kernels::GridShape metre_cells(std::uint32_t bits_x, std::uint32_t bits_y, std::uint32_t bits_z,
                                      std::uint32_t origin_x = 0) {
  kernels::GridShape shape;
  shape.inverse_cell_size = 1.0f;
  shape.bits_x = bits_x;
  shape.bits_y = bits_y;
  shape.bits_z = bits_z;
  shape.origin_x = origin_x;
  return shape;
}

// A stable counting sort of the particles by sort_key(x) < key_count; returns where each key's
// particles begin (key_count + 1 entries) and fills `sorted` with the particles in that order.
template <class SortKey>
std::vector<std::uint32_t> counting_sort(const std::vector<kernels::Vec4>& particles, std::uint32_t key_count,
                                         SortKey&& sort_key, std::vector<kernels::Vec4>& sorted) {
  std::vector<std::uint32_t> start(std::size_t{key_count} + 1, 0u), key(particles.size());
  for (std::size_t p = 0; p < particles.size(); ++p) key[p] = sort_key(kernels::xyz(particles[p]));
  for (const std::uint32_t k : key) ++start[k + 1];
  for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
  std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
  sorted.resize(particles.size());
  for (std::size_t p = 0; p < particles.size(); ++p) sorted[next[key[p]]++] = particles[p];
  return start;
}

inline SortedParticles sort_into_grid(const std::vector<kernels::Vec4>& particles, kernels::GridShape shape) {
  SortedParticles sorted{shape, {}, {}, {}, {}};
  sorted.cell_start = counting_sort(
      particles, shape.cell_count(), [&](kernels::Vec3 x) { return shape.key_of(x); }, sorted.position);
  return sorted;
}

// Sorted as the GPU's grid sorts them: by cell, each cell's lower half along x first
// (GridShape::in_upper_half), with cell_middle where each cell's upper half begins.
inline SortedParticles sort_into_half_cells(const std::vector<kernels::Vec4>& particles, kernels::GridShape shape) {
  SortedParticles sorted{shape, {}, {}, {}, {}};
  const std::vector<std::uint32_t> half_start = counting_sort(
      particles, 2 * shape.cell_count(),
      [&](kernels::Vec3 x) { return 2 * shape.key_of(x) + (shape.in_upper_half(x) ? 1u : 0u); }, sorted.position);
  for (std::uint32_t k = 0; k <= shape.cell_count(); ++k) sorted.cell_start.push_back(half_start[2 * k]);
  for (std::uint32_t k = 0; k < shape.cell_count(); ++k) sorted.cell_middle.push_back(half_start[2 * k + 1]);
  return sorted;
}

// Grid-walk test particles, sorted as the host sorts them or, with half_cells, as the GPU does:
// 2^3 x 2^2 x 2^2 cells of side 1 m, 300 particles spread over a 6 m cube (cells -3 to 3 on each
// axis: more than the grid's 4 along y and z, so distant particles share keys; across the period of
// 8 along x, so rows split there) and 400 packed into one cell, whose rows then hold many times 8
// candidates. origin_x: the grid's GridShape::origin_x.
inline SortedParticles clustered_particles(std::mt19937_64& random, bool half_cells = false,
                                           std::uint32_t origin_x = 0) {
  std::uniform_real_distribution<float> spread(-2.5f, 3.5f), packed(0.05f, 0.95f);
  std::vector<kernels::Vec4> particles;
  for (int p = 0; p < 300; ++p)
    particles.push_back(kernels::Vec4{spread(random), spread(random), spread(random), 0.0f});
  for (int p = 0; p < 400; ++p)
    particles.push_back(kernels::Vec4{packed(random), packed(random), packed(random), 0.0f});
  const kernels::GridShape shape = metre_cells(3, 2, 2, origin_x);
  return half_cells ? sort_into_half_cells(particles, shape) : sort_into_grid(particles, shape);
}

}  // namespace mssph::testing
