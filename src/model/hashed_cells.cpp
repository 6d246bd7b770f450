#include "model/hashed_cells.hpp"

#include "util/errors.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>

namespace mssph {

HashedCells::HashedCells(const std::vector<Eigen::Vector3d>& points, double side) : inverse_side_(1.0 / side) {
  const std::size_t n = points.size();
  mask_ = std::bit_ceil(std::max<std::size_t>(2 * n, 64)) - 1;
  std::vector<std::size_t> bucket(n);
  cell_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!points[i].allFinite()) throw SimulationFailure("a particle position is not finite (NaN or infinity)");
    cell_[i] = cell_of(points[i]);
    bucket[i] = bucket_of(cell_[i]);
  }
  starts_.assign(mask_ + 2, 0);
  for (std::size_t i = 0; i < n; ++i) ++starts_[bucket[i] + 1];
  std::partial_sum(starts_.begin(), starts_.end(), starts_.begin());
  std::vector<std::size_t> next(starts_.begin(), starts_.end() - 1);
  order_.resize(n);
  for (std::size_t i = 0; i < n; ++i) order_[next[bucket[i]]++] = i;
  sorted_points_.resize(n);
  sorted_cells_.resize(n);
  for (std::size_t s = 0; s < n; ++s) {
    sorted_points_[s] = points[order_[s]];
    sorted_cells_[s] = cell_[order_[s]];
  }
}

Eigen::Array3i HashedCells::cell_of(const Eigen::Vector3d& x) const {
  const Eigen::Array3d c = (x * inverse_side_).array().floor();
  if ((c.abs() > 1e9).any()) throw SimulationFailure("a particle is more than 1e9 cells away: the scene exploded");
  return c.cast<int>();
}

}  // namespace mssph
