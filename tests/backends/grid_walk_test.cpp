// The grid walk (kernels/common/cell_grid.hpp, CellRanges::for_each_candidate) that every
// neighbour sum goes through: for a team of any size, its lanes together visit each particle of the
// 27 cells around a point exactly once, each lane in the strided order that fixes a GPU sum's bits
// (candidates k, k + lanes, ... of each contiguous range); a walk that leaves out a body's rows
// (CellRanges::cell_body) skips exactly the ranges that hold nothing else. The expectation is built
// by brute force over all particles, cell by cell, not through the cell table. The particles are
// clustered so ranges run from empty to many times a team's width, in a grid small enough to wrap.
#include "common/cell_grid.hpp"
#include "common/particle_views.hpp"
#include "sorted_particles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

namespace mssph::testing {
namespace {

using kernels::Vec3;

// The contiguous ranges of the walk around x, each as the sorted indices it holds: a row of three
// cells along x when their keys are consecutive, else each cell alone; every cell's particles found
// by testing every particle's key.
std::vector<std::vector<std::uint32_t>> expected_ranges(const SortedParticles& sorted, Vec3 x) {
  const kernels::GridShape& shape = sorted.shape;
  int cx, cy, cz;
  shape.cell_of(x, cx, cy, cz);
  const auto cell_particles = [&](std::uint32_t key) {
    std::vector<std::uint32_t> in_cell;
    for (std::uint32_t s = 0; s < sorted.position.size(); ++s) {
      if (shape.key_of(kernels::xyz(sorted.position[s])) == key) in_cell.push_back(s);
    }
    return in_cell;
  };
  std::vector<std::vector<std::uint32_t>> ranges;
  for (int dz = -1; dz <= 1; ++dz) {
    for (int dy = -1; dy <= 1; ++dy) {
      const bool one_row = shape.key(cx + 1, cy + dy, cz + dz) == shape.key(cx - 1, cy + dy, cz + dz) + 2;
      if (one_row) ranges.emplace_back();
      for (int dx = -1; dx <= 1; ++dx) {
        if (!one_row) ranges.emplace_back();
        const std::vector<std::uint32_t> in_cell = cell_particles(shape.key(cx + dx, cy + dy, cz + dz));
        ranges.back().insert(ranges.back().end(), in_cell.begin(), in_cell.end());
      }
    }
  }
  return ranges;
}

// Each lane of a team of `lanes` walks around x; its visits must be its strided share of every
// range, and together the lanes must visit every particle of the ranges once.
void expect_team_walk(const SortedParticles& sorted, Vec3 x, const std::vector<std::vector<std::uint32_t>>& ranges,
                      std::uint32_t lanes) {
  SCOPED_TRACE(::testing::Message() << lanes << " lanes");
  std::vector<int> times_visited(sorted.position.size(), 0);
  for (std::uint32_t lane = 0; lane < lanes; ++lane) {
    std::vector<std::uint32_t> visits;
    sorted.grid().for_each_candidate(x, lane, lanes, [&](std::uint32_t t) { visits.push_back(t); });
    std::vector<std::uint32_t> expected;
    for (const std::vector<std::uint32_t>& range : ranges) {
      for (std::size_t k = lane; k < range.size(); k += lanes) expected.push_back(range[k]);
    }
    ASSERT_EQ(visits.size(), expected.size()) << "lane " << lane;
    for (std::size_t k = 0; k < visits.size(); ++k) {
      ASSERT_EQ(visits[k], expected[k]) << "lane " << lane << ", visit " << k;
      ++times_visited[visits[k]];
    }
  }
  for (const std::vector<std::uint32_t>& range : ranges) {
    for (const std::uint32_t s : range) ASSERT_EQ(times_visited[s], 1) << "particle " << s;
  }
}

// The points the walks start from: 100 particles (every 7th), then 100 random points over the
// particles' spread and beyond.
std::vector<Vec3> query_points(const SortedParticles& sorted, std::mt19937_64& random) {
  std::uniform_real_distribution<float> query(-3.0f, 4.0f);
  std::vector<Vec3> points;
  for (int q = 0; q < 100; ++q) points.push_back(kernels::xyz(sorted.position[q * 7]));
  for (int q = 0; q < 100; ++q) points.push_back(Vec3{query(random), query(random), query(random)});
  return points;
}

TEST(GridWalk, EveryLaneVisitsItsStridedShareOfEachRange) {
  std::mt19937_64 random(20261124);
  const SortedParticles sorted = clustered_particles(random);
  const std::vector<Vec3> points = query_points(sorted, random);
  std::size_t longest_range = 0, wrapped_walks = 0;
  for (std::size_t q = 0; q < points.size(); ++q) {
    SCOPED_TRACE(::testing::Message() << "query " << q);
    const Vec3 x = points[q];
    const std::vector<std::vector<std::uint32_t>> ranges = expected_ranges(sorted, x);
    if (ranges.size() > 9) ++wrapped_walks;
    for (const std::vector<std::uint32_t>& range : ranges) longest_range = std::max(longest_range, range.size());
    for (const std::uint32_t lanes : {1u, 2u, 3u, 4u, 8u}) expect_team_walk(sorted, x, ranges, lanes);
    if (HasFatalFailure()) return;
  }
  // The walk's corner cases were met: a row of many turns of 8 lanes, and rows split where the grid
  // wraps.
  EXPECT_GT(longest_range, 8u * 4u);
  EXPECT_GT(wrapped_walks, 0u);
}

// The one-lane walk of the large GPU scenes' force sums (for_each_candidate_within) visits the
// candidates of for_each_candidate that lie within the radius, in the same order, also where a
// range holds more than the 32 candidates of one mask.
TEST(GridWalk, TheWalkWithinARadiusVisitsTheNearCandidatesInTheWalksOrder) {
  std::mt19937_64 random(20261127);
  const SortedParticles sorted = clustered_particles(random);
  const kernels::CellRanges grid = sorted.grid();
  const std::vector<Vec3> points = query_points(sorted, random);
  std::size_t near_beyond_a_mask = 0, candidates_left_out = 0;
  for (std::size_t q = 0; q < points.size(); ++q) {
    SCOPED_TRACE(::testing::Message() << "query " << q);
    const Vec3 x = points[q];
    const std::vector<std::vector<std::uint32_t>> ranges = expected_ranges(sorted, x);
    for (const float radius : {0.3f, 1.0f}) {
      const float radius2 = radius * radius;
      std::vector<std::uint32_t> expected;
      for (const std::vector<std::uint32_t>& range : ranges) {
        for (std::size_t k = 0; k < range.size(); ++k) {
          if (kernels::squared_norm(x - kernels::xyz(sorted.position[range[k]])) < radius2) {
            expected.push_back(range[k]);
            if (k >= 32) ++near_beyond_a_mask;
          } else {
            ++candidates_left_out;
          }
        }
      }
      std::vector<std::uint32_t> visits;
      grid.for_each_candidate_within(x, radius2, sorted.position.data(), [&](std::uint32_t t) { visits.push_back(t); });
      ASSERT_EQ(visits, expected) << "radius " << radius;
    }
  }
  EXPECT_GT(near_beyond_a_mask, 0u);
  EXPECT_GT(candidates_left_out, 0u);
}

// The whole walk's visits, one lane, for comparison with a walk that leaves cells out.
std::vector<std::uint32_t> whole_walk(const kernels::CellRanges& grid, Vec3 x) {
  std::vector<std::uint32_t> visits;
  grid.for_each_candidate(x, [&](std::uint32_t t) { visits.push_back(t); });
  return visits;
}

// A walk given a radius visits, in the whole walk's order, a part of its candidates that holds
// every candidate a float test r^2 < radius^2 passes.
void expect_walk_within(const SortedParticles& sorted, Vec3 x, float radius2, std::size_t& visited,
                        std::size_t& whole) {
  const kernels::CellRanges grid = sorted.grid();
  std::vector<std::uint32_t> visits;
  grid.for_each_candidate(x, 0, 1, [&](std::uint32_t t) { visits.push_back(t); }, kernels::kNoBody, radius2);
  const std::vector<std::uint32_t> all = whole_walk(grid, x);
  std::size_t next = 0;  // the next visit to find in the whole walk
  for (const std::uint32_t t : all) {
    const bool visited_here = next < visits.size() && visits[next] == t;
    if (visited_here) ++next;
    if (kernels::squared_norm(x - kernels::xyz(sorted.position[t])) < radius2) {
      ASSERT_TRUE(visited_here) << "candidate " << t << " within the radius";
    }
  }
  ASSERT_EQ(next, visits.size()) << "visits out of the whole walk's order";
  visited += visits.size();
  whole += all.size();
}

// Particles spread evenly over the grid's whole period (8 x 4 x 4 cells of 1 m), so every cell
// holds as many on average.
SortedParticles evenly_spread(std::mt19937_64& random, int count) {
  std::uniform_real_distribution<float> along_x(0.0f, 8.0f), across(0.0f, 4.0f);
  std::vector<kernels::Vec4> particles;
  for (int p = 0; p < count; ++p) particles.push_back(kernels::Vec4{along_x(random), across(random), across(random), 0.0f});
  kernels::GridShape shape;
  shape.inverse_cell_size = 1.0f;
  shape.bits_x = 3;
  return sort_into_grid(particles, shape);
}

// At a radius of one cell (h, the sums' support), a walk from a point anywhere in its cell needs
// on average 3 cells of its own row, 1 + 2 pi / 4 of each of the four rows beside it and
// pi / 4 + pi / 3 of each of the four corner rows (the parts of the neighbouring cells that a
// sphere of radius h reaches): 20.61 of the 27 cells. Evenly spread particles give that fraction
// of the candidates, within the sampling noise; smaller radii leave out more, and the walks keep
// every candidate within the radius, rows split where the grid wraps included.
TEST(GridWalk, AWalkWithinARadiusLeavesOutTheCellsBeyondIt) {
  std::mt19937_64 random(20261128);
  const SortedParticles sorted = evenly_spread(random, 8 * 4 * 4 * 40);
  std::uniform_real_distribution<float> along_x(0.0f, 8.0f), across(0.0f, 4.0f);
  for (const float radius : {1.0f, 0.6f}) {
    std::size_t visited = 0, whole = 0;
    for (int q = 0; q < 400; ++q) {
      SCOPED_TRACE(::testing::Message() << "radius " << radius << ", query " << q);
      expect_walk_within(sorted, Vec3{along_x(random), across(random), across(random)}, radius * radius, visited, whole);
      if (HasFatalFailure()) return;
    }
    const double fraction = static_cast<double>(visited) / static_cast<double>(whole);
    if (radius == 1.0f) {
      const double expected = (3.0 + 4.0 * (1.0 + 2.0 * std::numbers::pi / 4.0) + 4.0 * (std::numbers::pi / 4.0 + std::numbers::pi / 3.0)) / 27.0;
      EXPECT_NEAR(fraction, expected, 0.02);  // 400 queries of ~1,000 candidates: noise ~0.005
    } else {
      EXPECT_LT(fraction, 0.6);
    }
  }
}

// The float coordinate nearest the face between cells k - 1 and k that the shape's own arithmetic
// puts in cell `in` (k - 1 or k).
float next_to_face(const kernels::GridShape& shape, int k, int in) {
  float x = static_cast<float>(k) / shape.inverse_cell_size;
  const float away = in < k ? -1e30f : 1e30f;
  while (static_cast<int>(std::floor(shape.in_cells(x))) != in) x = std::nextafter(x, away);
  return x;
}

// A candidate just across one, two or three faces of a point's cell, at nearly the radius: the
// walk must visit it whenever the float test r^2 < radius^2 passes. Cells of 13.7 mm, whose
// inverse is not exact, near the origin and 1,000 cells from it, where the coordinates' rounding
// is a sizeable part of a gap.
TEST(GridWalk, AWalkWithinARadiusKeepsTheCandidatesAtTheRadiusAcrossAFace) {
  std::mt19937_64 random(20261129);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::uniform_int_distribution<int> cell(-3, 3), which_axes(1, 7), side(0, 1);
  kernels::GridShape shape;
  const float h = 0.0137f;
  shape.inverse_cell_size = 1.0f / h;
  shape.bits_x = 3;
  for (const int origin : {0, 1000}) {
    // The gaps' spread about the radius: wider where the coordinates are coarser.
    std::uniform_real_distribution<float> relative(origin == 0 ? -4e-6f : -2e-4f, origin == 0 ? 4e-6f : 2e-4f);
    for (const float radius : {h, 0.7f * h}) {
      std::vector<kernels::Vec4> particles;
      std::vector<Vec3> points;
      while (points.size() < 1000) {
        const int axes = which_axes(random);  // the faces crossed, one bit per axis
        // Gaps to the crossed faces whose squares add up to the radius's, up to `relative`; the
        // point's other coordinates anywhere in its cell.
        float weight[3] = {0, 0, 0}, total = 0;
        for (int a = 0; a < 3; ++a) {
          if (axes & (1 << a)) total += (weight[a] = 0.05f + unit(random));
        }
        float point[3], candidate[3];
        bool in_its_cell = true;
        for (int a = 0; a < 3; ++a) {
          const int corner = origin + cell(random);
          const float lower = static_cast<float>(corner) * h;
          if (axes & (1 << a)) {
            const float gap = std::fmin(radius * std::sqrt(weight[a] / total) * (1.0f + relative(random)), 0.999f * h);
            const bool below = side(random) == 0;
            point[a] = below ? lower + gap : lower + h - gap;
            candidate[a] = below ? next_to_face(shape, corner, corner - 1) : next_to_face(shape, corner + 1, corner + 1);
          } else {
            point[a] = lower + unit(random) * h;
            candidate[a] = point[a];
          }
          in_its_cell = in_its_cell && static_cast<int>(std::floor(shape.in_cells(point[a]))) == corner;
        }
        if (!in_its_cell) continue;  // rounding put the point in the next cell: not the case meant
        points.push_back(Vec3{point[0], point[1], point[2]});
        particles.push_back(kernels::Vec4{candidate[0], candidate[1], candidate[2], 0.0f});
      }
      const SortedParticles sorted = sort_into_grid(particles, shape);
      std::size_t visited = 0, whole = 0, within_by_a_hair = 0;
      const float radius2 = radius * radius;
      for (std::size_t q = 0; q < points.size(); ++q) {
        SCOPED_TRACE(::testing::Message() << "origin " << origin << " cells, radius " << radius << ", query " << q);
        expect_walk_within(sorted, points[q], radius2, visited, whole);
        if (HasFatalFailure()) return;
        const float r2 = kernels::squared_norm(points[q] - kernels::xyz(particles[q]));
        if (r2 < radius2 && r2 > radius2 * (1.0f - 4e-4f)) ++within_by_a_hair;
      }
      // Some candidates lay within the radius by a few parts in ten thousand (1,000 cells out,
      // coordinates are 7e-5 cells apart); the walks left some out.
      EXPECT_GT(within_by_a_hair, 10u);
      EXPECT_LT(visited, whole);
    }
  }
}

// A cell's entry names the body its particles share, else marks it mixed; so does a body whose
// index does not fit the entry's 16 bits, which must not alias another body.
TEST(CellBody, NamesTheBodyAllOfACellsParticlesShareElseMarksTheCellMixed) {
  const auto entry = [](const std::vector<std::uint32_t>& bodies) {
    return kernels::cell_body_code(static_cast<std::uint32_t>(bodies.size()),
                                   [&](std::uint32_t k) { return bodies[k]; });
  };
  EXPECT_EQ(entry({5}), 5u);
  EXPECT_EQ(entry({7, 7, 7}), 7u);
  EXPECT_EQ(entry({7, 7, 3}), kernels::kMixedCell);
  EXPECT_EQ(entry({3, 7, 7}), kernels::kMixedCell);
  EXPECT_EQ(entry({0xfffeu, 0xfffeu}), 0xfffeu);
  EXPECT_EQ(entry({0xffffu}), kernels::kMixedCell);
  EXPECT_EQ(entry({0x10007u, 0x10007u}), kernels::kMixedCell);
}

// The clustered particles as three bodies: body 1 left of x = 0.5 m, body 2 right of it, every
// 13th particle body 3; the cells' entries as the GPU's grid writes them, empty cells' set to
// kMixedCell, as a stale entry may be.
SortedParticles three_bodies(std::mt19937_64& random) {
  SortedParticles sorted = clustered_particles(random);
  for (std::size_t s = 0; s < sorted.position.size(); ++s) {
    const std::uint32_t body = s % 13 == 0 ? 3u : sorted.position[s].x < 0.5f ? 1u : 2u;
    sorted.position[s].w = kernels::index_as_float_bits(body);
  }
  sorted.note_cell_bodies(kernels::kMixedCell);
  return sorted;
}

// A walk that leaves out a body visits, lane by lane, what a full walk would over every range of
// expected_ranges but those whose particles all belong to that body.
TEST(GridWalk, LeavesOutTheRowsThatHoldNothingButTheBodyLeftOut) {
  std::mt19937_64 random(20261128);
  const SortedParticles sorted = three_bodies(random);
  const kernels::CellRanges grid = sorted.grid();
  const std::vector<Vec3> points = query_points(sorted, random);
  std::size_t rows_left_out = 0, rows_kept = 0;
  for (std::size_t q = 0; q < points.size(); ++q) {
    SCOPED_TRACE(::testing::Message() << "query " << q);
    const Vec3 x = points[q];
    for (const std::uint32_t left_out : {1u, 2u, 3u, kernels::kNoBody}) {
      SCOPED_TRACE(::testing::Message() << "body left out " << left_out);
      std::vector<std::vector<std::uint32_t>> kept;
      for (const std::vector<std::uint32_t>& range : expected_ranges(sorted, x)) {
        if (range.empty()) continue;
        const bool only_left_out = std::all_of(range.begin(), range.end(), [&](std::uint32_t t) {
          return kernels::body_of(sorted.position[t]) == left_out;
        });
        if (only_left_out) {
          ++rows_left_out;
        } else {
          kept.push_back(range);
          if (left_out != kernels::kNoBody) ++rows_kept;
        }
      }
      for (const std::uint32_t lanes : {1u, 3u, 8u}) {
        for (std::uint32_t lane = 0; lane < lanes; ++lane) {
          std::vector<std::uint32_t> visits, expected;
          grid.for_each_candidate(x, lane, lanes, [&](std::uint32_t t) { visits.push_back(t); }, left_out);
          for (const std::vector<std::uint32_t>& range : kept) {
            for (std::size_t k = lane; k < range.size(); k += lanes) expected.push_back(range[k]);
          }
          ASSERT_EQ(visits, expected) << "lane " << lane << " of " << lanes;
        }
      }
    }
  }
  EXPECT_GT(rows_left_out, 100u);
  EXPECT_GT(rows_kept, 100u);
}

}  // namespace
}  // namespace mssph::testing
