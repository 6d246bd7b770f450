#include "fluid_fill.hpp"

#include <cmath>
#include <unordered_map>

namespace mssph {
namespace {

struct CellHash {
  std::size_t operator()(const Eigen::Vector3i& c) const {
    return (static_cast<std::size_t>(c.x()) * 73856093u) ^ (static_cast<std::size_t>(c.y()) * 19349663u) ^
           (static_cast<std::size_t>(c.z()) * 83492791u);
  }
};

}  // namespace

std::vector<Eigen::Vector3d> sites_clear_of(const std::vector<Eigen::Vector3d>& candidates,
                                            const std::vector<Eigen::Vector3d>& others, double distance) {
  const auto cell_of = [&](const Eigen::Vector3d& x) {
    return Eigen::Vector3i((x / distance).array().floor().cast<int>());
  };
  std::unordered_map<Eigen::Vector3i, std::vector<std::size_t>, CellHash> cells;
  for (std::size_t j = 0; j < others.size(); ++j) cells[cell_of(others[j])].push_back(j);
  // A site exactly `distance` from another body's site continues the lattice and stays, whatever
  // the rounding of the two lattices' positions.
  const double distance_squared = distance * distance * (1.0 - 1e-9);
  std::vector<Eigen::Vector3d> clear;
  for (const Eigen::Vector3d& x : candidates) {
    const Eigen::Vector3i c = cell_of(x);
    bool near = false;
    for (int dz = -1; dz <= 1 && !near; ++dz) {
      for (int dy = -1; dy <= 1 && !near; ++dy) {
        for (int dx = -1; dx <= 1 && !near; ++dx) {
          const auto it = cells.find(c + Eigen::Vector3i(dx, dy, dz));
          if (it == cells.end()) continue;
          for (std::size_t j : it->second) {
            if ((others[j] - x).squaredNorm() < distance_squared) {
              near = true;
              break;
            }
          }
        }
      }
    }
    if (!near) clear.push_back(x);
  }
  return clear;
}

}  // namespace mssph
