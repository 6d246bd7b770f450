#pragma once
// Points bucketed in cubic cells by spatial hashing (Teschner et al. 2003): cells of side `side`
// hashed into a table of 2^k buckets, at least twice as many as points, the points counting-sorted
// by bucket into contiguous arrays. Unlike a dense grid it needs no bounding box, so a point far
// away costs nothing; unlike a map of cells it allocates nothing per cell. Every point within
// `side` of x lies in x's cell or one of its 26 neighbours. The double-precision neighbour search
// (neighbour_search.hpp) and the start-up checks that compare point sets walk it.
#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace mssph {

class HashedCells {
 public:
  // Throws SimulationFailure for a point that is not finite or lies more than 1e9 cells away.
  HashedCells(const std::vector<Eigen::Vector3d>& points, double side);

  Eigen::Array3i cell_of(const Eigen::Vector3d& x) const;
  const Eigen::Array3i& cell(std::size_t i) const { return cell_[i]; }

  // Calls visit(j, x_j) for every point j in the 27 cells around `centre`, bucket by bucket. A
  // visit that returns bool stops the walk by returning false.
  template <class Visit>
  void for_each_in_neighbourhood(const Eigen::Array3i& centre, Visit&& visit) const {
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const Eigen::Array3i c = centre + Eigen::Array3i(dx, dy, dz);
          const std::size_t b = bucket_of(c);
          for (std::size_t s = starts_[b]; s < starts_[b + 1]; ++s) {
            if (!(sorted_cells_[s] == c).all()) continue;  // another cell in the same bucket
            if constexpr (std::is_same_v<decltype(visit(order_[s], sorted_points_[s])), bool>) {
              if (!visit(order_[s], sorted_points_[s])) return;
            } else {
              visit(order_[s], sorted_points_[s]);
            }
          }
        }
      }
    }
  }
  // The same around point x, which need not be one of the points.
  template <class Visit>
  void for_each_near(const Eigen::Vector3d& x, Visit&& visit) const {
    for_each_in_neighbourhood(cell_of(x), visit);
  }

 private:
  std::size_t bucket_of(const Eigen::Array3i& c) const {
    const auto u = c.cast<std::uint32_t>();
    return static_cast<std::size_t>((u.x() * 73856093u) ^ (u.y() * 19349663u) ^ (u.z() * 83492791u)) & mask_;
  }

  double inverse_side_;
  std::size_t mask_ = 0;
  std::vector<Eigen::Array3i> cell_;            // cell of point i
  std::vector<std::size_t> starts_;             // bucket b: order_[starts_[b] .. starts_[b + 1])
  std::vector<std::size_t> order_;              // point indices sorted by bucket
  std::vector<Eigen::Vector3d> sorted_points_;  // points[order_[s]], contiguous per bucket
  std::vector<Eigen::Array3i> sorted_cells_;    // cell_[order_[s]]
};

}  // namespace mssph
