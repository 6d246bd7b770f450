#include "model/neighbour_search.hpp"

#include "model/hashed_cells.hpp"

#include <algorithm>
#include <numeric>

#include <omp.h>

namespace mssph {

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
