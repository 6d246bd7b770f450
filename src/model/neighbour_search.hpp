#pragma once
// Uniform-grid neighbour search with cell size h (the support radius): the neighbours of a
// particle lie in its own cell and the 26 around it. Output is a compressed list per particle
// (itself included). Double precision: the rest state's neighbours are found with it once, and the
// reference backend's every step.
#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace mssph {

struct NeighbourLists {
  std::vector<std::size_t> offsets;  // neighbours of i: indices[offsets[i] .. offsets[i + 1])
  std::vector<std::size_t> indices;

  std::size_t count(std::size_t i) const { return offsets[i + 1] - offsets[i]; }
  const std::size_t* begin(std::size_t i) const { return indices.data() + offsets[i]; }
  const std::size_t* end(std::size_t i) const { return indices.data() + offsets[i + 1]; }
};

// All j with |x_i - x_j| < h, for every i. Throws SimulationFailure if a position is not finite.
NeighbourLists find_neighbours(const std::vector<Eigen::Vector3d>& positions, double h);

}  // namespace mssph
