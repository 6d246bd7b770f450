// The grid walk (kernels/common/cell_grid.hpp, CellRanges::for_each_candidate) that every
// neighbour sum goes through: for a team of any size, its lanes together visit each particle of the
// 27 cells around a point exactly once, each lane in the strided order that fixes a GPU sum's bits
// (candidates k, k + lanes, ... of each contiguous range); a walk that leaves out a body's rows
// (CellRanges::cell_body) skips exactly the ranges that hold nothing else. The expectation is built
// by brute force over all particles, cell by cell, not through the cell table. The particles are
// clustered so ranges run from empty to many times a team's width, in a grid small enough to wrap.
#include "common/cell_grid.hpp"
#include "common/fluid_physics.hpp"
#include "common/particle_views.hpp"
#include "sorted_particles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
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
// range holds more than the 32 candidates of one mask, and where the walk finds more segments
// with a near candidate than it can hold (capacities of 1 and 3), so it visits them in several goes.
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
      const auto expect_visits = [&](auto held) {
        std::vector<std::uint32_t> visits;
        grid.for_each_candidate_within(x, radius2, sorted.position.data(), held,
                                       [&](std::uint32_t t) { visits.push_back(t); });
        ASSERT_EQ(visits, expected) << "radius " << radius << ", " << held.capacity << " segments held";
      };
      expect_visits(kernels::HeldSegments<1>{});
      expect_visits(kernels::HeldSegments<3>{});
      expect_visits(kernels::HeldSegments<kernels::kHeldSegments>{});
      if (HasFatalFailure()) return;
    }
  }
  EXPECT_GT(near_beyond_a_mask, 0u);
  EXPECT_GT(candidates_left_out, 0u);
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
