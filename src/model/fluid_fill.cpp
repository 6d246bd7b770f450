#include "fluid_fill.hpp"

#include "hashed_cells.hpp"

namespace mssph {

std::vector<Eigen::Vector3d> sites_clear_of(const std::vector<Eigen::Vector3d>& candidates,
                                            const std::vector<Eigen::Vector3d>& others, double distance) {
  const HashedCells cells(others, distance);
  // A site exactly `distance` from another body's site continues the lattice and stays, whatever
  // the rounding of the two lattices' positions.
  const double distance_squared = distance * distance * (1.0 - 1e-9);
  std::vector<Eigen::Vector3d> clear;
  for (const Eigen::Vector3d& x : candidates) {
    bool near = false;
    cells.for_each_near(x, [&](std::size_t, const Eigen::Vector3d& other) {
      near = (other - x).squaredNorm() < distance_squared;
      return !near;
    });
    if (!near) clear.push_back(x);
  }
  return clear;
}

}  // namespace mssph
