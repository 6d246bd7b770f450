#include "model/neighbour_search.hpp"

#include "util/errors.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numeric>

#include <omp.h>

namespace mssph {
namespace {

// Spatial hashing (Teschner et al. 2003): cells of side h are hashed into a table of 2^k buckets,
// k chosen so there are at least twice as many buckets as particles. Unlike a dense grid this
// needs no bounding box, so one particle flung far away costs nothing. Particles are counting-
// sorted by bucket; a candidate from another cell that shares a bucket is recognised by its cell
// coordinates and skipped.
class HashedCells {
 public:
  HashedCells(const std::vector<Eigen::Vector3d>& positions, double h) : inverse_h_(1.0 / h) {
    const std::size_t n = positions.size();
    mask_ = std::bit_ceil(std::max<std::size_t>(2 * n, 64)) - 1;
    std::vector<std::size_t> bucket(n);
    cell_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (!positions[i].allFinite()) throw SimulationFailure("a particle position is not finite (NaN or infinity)");
      cell_[i] = cell_of(positions[i]);
      bucket[i] = bucket_of(cell_[i]);
    }
    starts_.assign(mask_ + 2, 0);
    for (std::size_t i = 0; i < n; ++i) ++starts_[bucket[i] + 1];
    std::partial_sum(starts_.begin(), starts_.end(), starts_.begin());
    std::vector<std::size_t> next(starts_.begin(), starts_.end() - 1);
    order_.resize(n);
    for (std::size_t i = 0; i < n; ++i) order_[next[bucket[i]]++] = i;
    sorted_positions_.resize(n);
    sorted_cells_.resize(n);
    for (std::size_t s = 0; s < n; ++s) {
      sorted_positions_[s] = positions[order_[s]];
      sorted_cells_[s] = cell_[order_[s]];
    }
  }

  const Eigen::Array3i& cell(std::size_t i) const { return cell_[i]; }

  // Calls visit(j, x_j) for every particle j in the 27 cells around `centre`.
  template <class Visit>
  void for_each_in_neighbourhood(const Eigen::Array3i& centre, Visit&& visit) const {
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const Eigen::Array3i c = centre + Eigen::Array3i(dx, dy, dz);
          const std::size_t b = bucket_of(c);
          for (std::size_t s = starts_[b]; s < starts_[b + 1]; ++s) {
            if ((sorted_cells_[s] == c).all()) visit(order_[s], sorted_positions_[s]);
          }
        }
      }
    }
  }

 private:
  Eigen::Array3i cell_of(const Eigen::Vector3d& x) const {
    const Eigen::Array3d c = (x * inverse_h_).array().floor();
    if ((c.abs() > 1e9).any())
      throw SimulationFailure("a particle is more than 1e9 smoothing lengths away: the scene exploded");
    return c.cast<int>();
  }
  std::size_t bucket_of(const Eigen::Array3i& c) const {
    const auto u = c.cast<std::uint32_t>();
    return static_cast<std::size_t>((u.x() * 73856093u) ^ (u.y() * 19349663u) ^ (u.z() * 83492791u)) & mask_;
  }

  double inverse_h_;
  std::size_t mask_ = 0;
  std::vector<Eigen::Array3i> cell_;               // cell of particle i
  std::vector<std::size_t> starts_;                // bucket b: order_[starts_[b] .. starts_[b + 1])
  std::vector<std::size_t> order_;                 // particle indices sorted by bucket
  std::vector<Eigen::Vector3d> sorted_positions_;  // positions[order_[s]], contiguous per bucket
  std::vector<Eigen::Array3i> sorted_cells_;       // cell_[order_[s]]
};

}  // namespace

NeighbourLists find_neighbours(const std::vector<Eigen::Vector3d>& positions, double h) {
  const std::size_t n = positions.size();
  NeighbourLists lists;
  lists.offsets.assign(n + 1, 0);
  if (n == 0) return lists;
  const HashedCells cells(positions, h);
  const double h2 = h * h;

  // One search per particle: each thread takes a contiguous range of particles and gathers their
  // lists in its own buffer; the buffers are then concatenated in particle order. The visiting
  // order depends only on the positions, never on the thread count, so sums over these lists are
  // reproducible.
#pragma omp parallel
  {
    const std::size_t threads = static_cast<std::size_t>(omp_get_num_threads());
    const std::size_t thread = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t first = n * thread / threads;
    const std::size_t last = n * (thread + 1) / threads;
    std::vector<std::size_t> found;
    found.reserve((last - first) * 64);
    for (std::size_t i = first; i < last; ++i) {
      const Eigen::Vector3d x_i = positions[i];
      const std::size_t before = found.size();
      cells.for_each_in_neighbourhood(cells.cell(i), [&](std::size_t j, const Eigen::Vector3d& x_j) {
        if ((x_i - x_j).squaredNorm() < h2) found.push_back(j);
      });
      lists.offsets[i + 1] = found.size() - before;
    }
#pragma omp barrier
#pragma omp single
    {
      std::partial_sum(lists.offsets.begin(), lists.offsets.end(), lists.offsets.begin());
      lists.indices.resize(lists.offsets[n]);
    }  // implicit barrier
    std::copy(found.begin(), found.end(), lists.indices.begin() + static_cast<std::ptrdiff_t>(lists.offsets[first]));
  }
  return lists;
}

}  // namespace mssph
