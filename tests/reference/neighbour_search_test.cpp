// The hashed-grid neighbour search against brute force.
#include "model/neighbour_search.hpp"

#include "util/errors.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>

namespace mssph::reference {
namespace {

std::vector<std::size_t> brute_force(const std::vector<Eigen::Vector3d>& x, std::size_t i, double h) {
  std::vector<std::size_t> out;
  for (std::size_t j = 0; j < x.size(); ++j) {
    if ((x[i] - x[j]).squaredNorm() < h * h) out.push_back(j);
  }
  return out;
}

TEST(NeighbourSearch, MatchesBruteForceOnRandomClouds) {
  std::mt19937 random(42);
  for (const double h : {0.03, 0.1}) {
    std::uniform_real_distribution<double> u(-0.2, 0.2);
    std::vector<Eigen::Vector3d> x(1500);
    for (auto& p : x) p = Eigen::Vector3d(u(random), u(random), u(random));
    x.push_back(Eigen::Vector3d(1e3, -2e3, 5e2));  // far away: must not break the grid
    x.push_back(x[0]);                             // a coincident pair
    const NeighbourLists lists = find_neighbours(x, h);
    for (std::size_t i = 0; i < x.size(); ++i) {
      std::vector<std::size_t> found(lists.begin(i), lists.end(i));
      std::sort(found.begin(), found.end());
      EXPECT_EQ(found, brute_force(x, i, h)) << "particle " << i << ", h = " << h;
    }
  }
}

TEST(NeighbourSearch, NonFinitePositionIsASimulationFailure) {
  std::vector<Eigen::Vector3d> x{{0, 0, 0}, {std::numeric_limits<double>::quiet_NaN(), 0, 0}};
  EXPECT_THROW(find_neighbours(x, 0.1), SimulationFailure);
}

}  // namespace
}  // namespace mssph::reference
