// The hashed cells (model/hashed_cells.hpp) against brute force: around any point, the points of
// the 27 cells about its own cell and no others, though cells far apart share buckets, each once
// and a cell's points in index order; a visit that returns false ends the walk.
#include "model/hashed_cells.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace mssph::reference {
namespace {

// Whether point p lies in the 27 cells of side `side` about x's cell.
bool in_neighbourhood(const Eigen::Vector3d& x, const Eigen::Vector3d& p, double side) {
  for (int k = 0; k < 3; ++k) {
    if (std::abs(std::floor(p[k] / side) - std::floor(x[k] / side)) > 1.0) return false;
  }
  return true;
}

TEST(HashedCells, VisitsExactlyThePointsOfTheTwentySevenCellsInIndexOrder) {
  std::mt19937 random(7);
  const double side = 0.05;
  // Few points in a wide box: hundreds of cells a bucket, so buckets hold points of several cells.
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  std::vector<Eigen::Vector3d> points(400);
  for (auto& p : points) p = Eigen::Vector3d(u(random), u(random), u(random));
  std::uniform_real_distribution<double> near(-0.1, 0.1);
  for (int k = 0; k < 200; ++k)
    points.push_back(points[k % 10] + Eigen::Vector3d(near(random), near(random), near(random)));
  const HashedCells cells(points, side);
  for (std::size_t q = 0; q < points.size(); q += 3) {
    const Eigen::Vector3d x = points[q] + Eigen::Vector3d(0.3 * side, -0.2 * side, 0.1 * side);
    std::vector<std::size_t> expected;
    for (std::size_t j = 0; j < points.size(); ++j) {
      if (in_neighbourhood(x, points[j], side)) expected.push_back(j);
    }
    std::vector<std::size_t> visited;
    std::vector<Eigen::Array3i> visited_cell;
    cells.for_each_near(x, [&](std::size_t j, const Eigen::Vector3d& p) {
      EXPECT_EQ(p, points[j]);
      if (!visited.empty() && (visited_cell.back() == cells.cell(j)).all()) {
        EXPECT_LT(visited.back(), j) << "a cell's points in index order";
      }
      visited.push_back(j);
      visited_cell.push_back(cells.cell(j));
    });
    std::vector<std::size_t> sorted = visited;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, expected) << "around point " << q;
  }
}

TEST(HashedCells, AVisitThatReturnsFalseEndsTheWalk) {
  const std::vector<Eigen::Vector3d> points{{0.01, 0.01, 0.01}, {0.02, 0.01, 0.01}, {0.03, 0.01, 0.01}};
  const HashedCells cells(points, 0.1);
  int visits = 0;
  cells.for_each_near(points[0], [&](std::size_t, const Eigen::Vector3d&) {
    ++visits;
    return false;
  });
  EXPECT_EQ(visits, 1);
  visits = 0;
  cells.for_each_near(points[0], [&](std::size_t, const Eigen::Vector3d&) { ++visits; });
  EXPECT_EQ(visits, 3);
}

}  // namespace
}  // namespace mssph::reference
