#pragma once
// Points bucketed in cubic cells of side `side` (a hash map of the occupied cells, so building and
// querying stay linear however the points spread): every point within `side` of x lies in x's
// cell or one of its 26 neighbours. The start-up checks that compare two point sets use it.
#include <Eigen/Core>

#include <cmath>
#include <unordered_map>
#include <vector>

namespace mssph {

class CellBuckets {
 public:
  CellBuckets(const std::vector<Eigen::Vector3d>& points, double side) : side_(side) {
    for (std::size_t j = 0; j < points.size(); ++j) cells_[cell_of(points[j])].push_back(j);
  }

  // Calls visit(j) for the index j of every point in x's cell and its 26 neighbours, a superset
  // of the points within `side` of x, until visit returns false.
  template <class Visit>
  void visit_near(const Eigen::Vector3d& x, Visit&& visit) const {
    const Eigen::Vector3i c = cell_of(x);
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const auto it = cells_.find(c + Eigen::Vector3i(dx, dy, dz));
          if (it == cells_.end()) continue;
          for (const std::size_t j : it->second) {
            if (!visit(j)) return;
          }
        }
      }
    }
  }

 private:
  struct CellHash {
    std::size_t operator()(const Eigen::Vector3i& c) const {
      return (static_cast<std::size_t>(c.x()) * 73856093u) ^ (static_cast<std::size_t>(c.y()) * 19349663u) ^
             (static_cast<std::size_t>(c.z()) * 83492791u);
    }
  };

  Eigen::Vector3i cell_of(const Eigen::Vector3d& x) const {
    return Eigen::Vector3i((x / side_).array().floor().cast<int>());
  }

  double side_;
  std::unordered_map<Eigen::Vector3i, std::vector<std::size_t>, CellHash> cells_;
};

}  // namespace mssph
