#include "neighbour_search.hpp"

#include "util/errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace mssph::reference {
namespace {

struct Cell {
  std::int64_t x, y, z;
};

// Cells are ordered by one 64-bit key (21 bits per axis, offset to be non-negative), which is
// enough for 2 million cells along each axis of the particles' bounding box.
std::uint64_t cell_key(const Cell& c) {
  return (static_cast<std::uint64_t>(c.x) << 42) | (static_cast<std::uint64_t>(c.y) << 21) |
         static_cast<std::uint64_t>(c.z);
}

}  // namespace

NeighbourLists find_neighbours(const std::vector<Eigen::Vector3d>& positions, double h) {
  const std::size_t n = positions.size();
  NeighbourLists lists;
  lists.offsets.assign(n + 1, 0);
  if (n == 0) return lists;

  Eigen::Vector3d lower = positions[0];
  for (const Eigen::Vector3d& x : positions) {
    if (!x.allFinite()) throw SimulationFailure("a particle position is not finite (NaN or infinity)");
    lower = lower.cwiseMin(x);
  }
  constexpr std::int64_t kMaxCells = (std::int64_t{1} << 21) - 2;
  const auto cell_of = [&](const Eigen::Vector3d& x) {
    const Eigen::Vector3d c = ((x - lower) / h).array().floor() + 1.0;  // +1: room for the -1 neighbour
    if ((c.array() > static_cast<double>(kMaxCells)).any()) {
      throw SimulationFailure("particles spread over more than 2 million smoothing lengths: the scene exploded");
    }
    return Cell{static_cast<std::int64_t>(c.x()), static_cast<std::int64_t>(c.y()), static_cast<std::int64_t>(c.z())};
  };

  // Sort particle indices by cell key; each cell is then a contiguous run.
  std::vector<std::uint64_t> key(n);
  for (std::size_t i = 0; i < n; ++i) key[i] = cell_key(cell_of(positions[i]));
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b] || (key[a] == key[b] && a < b); });
  std::vector<std::uint64_t> sorted_key(n);
  for (std::size_t s = 0; s < n; ++s) sorted_key[s] = key[order[s]];

  const double h2 = h * h;
  std::vector<std::vector<std::size_t>> per_particle(n);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    const Cell c = cell_of(positions[i]);
    std::vector<std::size_t>& found = per_particle[i];
    for (std::int64_t dz = -1; dz <= 1; ++dz) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
          const std::uint64_t k = cell_key({c.x + dx, c.y + dy, c.z + dz});
          auto first = std::lower_bound(sorted_key.begin(), sorted_key.end(), k);
          for (auto it = first; it != sorted_key.end() && *it == k; ++it) {
            const std::size_t j = order[static_cast<std::size_t>(it - sorted_key.begin())];
            if ((positions[i] - positions[j]).squaredNorm() < h2) found.push_back(j);
          }
        }
      }
    }
    std::sort(found.begin(), found.end());  // a fixed summation order: results do not depend on threads
  }
  for (std::size_t i = 0; i < n; ++i) lists.offsets[i + 1] = lists.offsets[i] + per_particle[i].size();
  lists.indices.resize(lists.offsets[n]);
  for (std::size_t i = 0; i < n; ++i) std::copy(per_particle[i].begin(), per_particle[i].end(), lists.indices.begin() + static_cast<std::ptrdiff_t>(lists.offsets[i]));
  return lists;
}

}  // namespace mssph::reference
