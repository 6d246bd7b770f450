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
#include <bitset>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace mssph::testing {
namespace {

using kernels::Vec3;

// Which half a walk from x trims where cells are split (CellRanges::trimmed_side), from x's place in
// its cell in double precision: +1 above the middle by kHalfTrimMargin, -1 below it by as much.
int side_trimmed_from(const SortedParticles& sorted, Vec3 x) {
  if (sorted.cell_middle.empty()) return 0;
  const double in_cells = static_cast<double>(x.x) * static_cast<double>(sorted.shape.inverse_cell_size);
  const double fraction = in_cells - std::floor(in_cells);
  const double margin = kernels::kHalfTrimMargin;
  return fraction >= 0.5 + margin ? 1 : fraction < 0.5 - margin ? -1 : 0;
}

// The contiguous ranges of the walk around x, each as the sorted indices it holds: a row of three
// cells along x when their keys are consecutive, else each cell alone; every cell's particles found
// by testing every particle's key. Where cells are split, the cell below x along x holds only its
// upper half's particles when x lies above its own cell's middle, the cell above only its lower
// half's when x lies below it (side_trimmed_from), unless `trim` is false.
std::vector<std::vector<std::uint32_t>> expected_ranges(const SortedParticles& sorted, Vec3 x, bool trim = true) {
  const kernels::GridShape& shape = sorted.shape;
  int cx, cy, cz;
  shape.cell_of(x, cx, cy, cz);
  const int side = trim ? side_trimmed_from(sorted, x) : 0;
  const auto trimmed = [&](int dx, std::uint32_t s) {
    const bool upper = shape.in_upper_half(kernels::xyz(sorted.position[s]));
    return (dx < 0 && side > 0 && !upper) || (dx > 0 && side < 0 && upper);
  };
  std::vector<std::uint32_t> key_of_particle(sorted.position.size());
  for (std::uint32_t s = 0; s < sorted.position.size(); ++s)
    key_of_particle[s] = shape.key_of(kernels::xyz(sorted.position[s]));
  const auto cell_particles = [&](std::uint32_t key, int dx) {
    std::vector<std::uint32_t> in_cell;
    for (std::uint32_t s = 0; s < sorted.position.size(); ++s) {
      if (key_of_particle[s] == key && !trimmed(dx, s)) in_cell.push_back(s);
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
        const std::vector<std::uint32_t> in_cell = cell_particles(shape.key(cx + dx, cy + dy, cz + dz), dx);
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

// The shifts of the grid's wrap along x (GridShape::origin_x) the walks are tested with: none, 3
// cells, -5 cells.
constexpr std::uint32_t kOrigins[] = {0u, 3u, 0u - 5u};

// Over whole cells (the host's sort) and over split ones (the GPU's: CellRanges::cell_middle).
TEST(GridWalk, EveryLaneVisitsItsStridedShareOfEachRange) {
  for (const bool half_cells : {false, true}) {
    for (const std::uint32_t origin_x : kOrigins) {
      SCOPED_TRACE(::testing::Message() << (half_cells ? "half cells" : "whole cells") << ", origin_x " << origin_x);
      std::mt19937_64 random(20261124);
      const SortedParticles sorted = clustered_particles(random, half_cells, origin_x);
      const std::vector<Vec3> points = query_points(sorted, random);
      std::size_t longest_range = 0, wrapped_walks = 0, trimmed_walks = 0;
      for (std::size_t q = 0; q < points.size(); ++q) {
        SCOPED_TRACE(::testing::Message() << "query " << q);
        const Vec3 x = points[q];
        // One lane trims halves; a team's lanes walk whole cells.
        const std::vector<std::vector<std::uint32_t>> ranges = expected_ranges(sorted, x);
        const std::vector<std::vector<std::uint32_t>> whole = expected_ranges(sorted, x, /*trim=*/false);
        if (ranges.size() > 9) ++wrapped_walks;
        if (side_trimmed_from(sorted, x) != 0) ++trimmed_walks;
        for (const std::vector<std::uint32_t>& range : whole) longest_range = std::max(longest_range, range.size());
        for (const std::uint32_t lanes : {1u, 2u, 3u, 4u, 8u}) {
          expect_team_walk(sorted, x, lanes == 1 ? ranges : whole, lanes);
        }
        if (HasFatalFailure()) return;
      }
      // The walk's corner cases were met: a row of many turns of 8 lanes, rows split where the grid
      // wraps, and (half cells) trimmed walks.
      EXPECT_GT(longest_range, 8u * 4u);
      EXPECT_GT(wrapped_walks, 0u);
      if (half_cells) {
        EXPECT_GT(trimmed_walks, 100u);
      }
    }
  }
}

// Particles and points at the halves' boundaries along x, in every cell from -3 to 3 m: fractions
// of a cell 0, 0.5 and 0.5 +- kHalfTrimMargin, each also a float step either side, and just below
// 1; y and z at random in the same cells.
std::vector<Vec3> on_half_boundaries(std::mt19937_64& random) {
  std::uniform_real_distribution<float> across(-3.0f, 4.0f);
  const float margin = kernels::kHalfTrimMargin;
  std::vector<float> fractions;
  for (const float f : {0.0f, 0.5f, 0.5f - margin, 0.5f + margin}) {
    fractions.push_back(f);
    fractions.push_back(std::nextafter(f, -1.0f));
    fractions.push_back(std::nextafter(f, 2.0f));
  }
  fractions.push_back(std::nextafter(1.0f, 0.0f));
  std::vector<Vec3> points;
  for (int cell = -3; cell <= 3; ++cell) {
    for (const float f : fractions) {
      for (int k = 0; k < 4; ++k) points.push_back(Vec3{static_cast<float>(cell) + f, across(random), across(random)});
    }
  }
  return points;
}

// Where cells are split, a walk trims only particles farther than a cell from its point: every
// particle closer than one cell (r^2 < 1 m^2 in float, as the sums test it) is visited, and once,
// also for particles and points on the halves' boundaries; and the trimming happened (walks that
// visited fewer candidates than the same walk over whole rows).
TEST(GridWalk, AWalkOverSplitCellsVisitsEveryParticleWithinACell) {
  for (const std::uint32_t origin_x : kOrigins) {
    SCOPED_TRACE(::testing::Message() << "origin_x " << origin_x);
    std::mt19937_64 random(20261128);
    std::uniform_real_distribution<float> spread(-2.5f, 3.5f);
    std::vector<kernels::Vec4> particles;
    for (const Vec3 x : on_half_boundaries(random)) particles.push_back(kernels::Vec4{x.x, x.y, x.z, 0.0f});
    for (int p = 0; p < 600; ++p) {
      particles.push_back(kernels::Vec4{spread(random), spread(random), spread(random), 0.0f});
    }
    const SortedParticles sorted = sort_into_half_cells(particles, metre_cells(3, 2, 2, origin_x));
    const kernels::CellRanges grid = sorted.grid();
    kernels::CellRanges whole_rows = grid;
    whole_rows.cell_middle = nullptr;
    std::vector<Vec3> points = on_half_boundaries(random);
    for (int q = 0; q < 200; ++q) points.push_back(Vec3{spread(random), spread(random), spread(random)});
    std::size_t trimmed_walks = 0, near_pairs = 0;
    for (std::size_t q = 0; q < points.size(); ++q) {
      SCOPED_TRACE(::testing::Message() << "query " << q);
      const Vec3 x = points[q];
      std::vector<int> times_visited(sorted.position.size(), 0);
      std::size_t visits = 0, whole_visits = 0;
      grid.for_each_candidate(x, [&](std::uint32_t t) {
        ++times_visited[t];
        ++visits;
      });
      whole_rows.for_each_candidate(x, [&](std::uint32_t) { ++whole_visits; });
      for (std::uint32_t t = 0; t < sorted.position.size(); ++t) {
        ASSERT_LE(times_visited[t], 1) << "particle " << t;
        if (kernels::squared_norm(x - kernels::xyz(sorted.position[t])) < 1.0f) {
          ++near_pairs;
          ASSERT_EQ(times_visited[t], 1) << "particle " << t << " within a cell was not visited";
        }
      }
      if (visits < whole_visits) ++trimmed_walks;
    }
    EXPECT_GT(trimmed_walks, 100u);
    EXPECT_GT(near_pairs, 1000u);
  }
}

// The one-lane walk of the large GPU scenes' force sums (for_each_candidate_within) visits the
// candidates of for_each_candidate that lie within the radius, in the same order, also where a
// range holds more than the 32 candidates of one mask, and where the walk finds more segments
// with a near candidate than it can hold (capacities of 1 and 3), so it visits them in several goes;
// over split cells, as the GPU's one-lane walks go.
TEST(GridWalk, TheWalkWithinARadiusVisitsTheNearCandidatesInTheWalksOrder) {
  std::mt19937_64 random(20261127);
  const SortedParticles sorted = clustered_particles(random, /*half_cells=*/true);
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
    return cell_body_code(static_cast<std::uint32_t>(bodies.size()), [&](std::uint32_t k) { return bodies[k]; });
  };
  EXPECT_EQ(entry({5}), 5u);
  EXPECT_EQ(entry({7, 7, 7}), 7u);
  EXPECT_EQ(entry({7, 7, 3}), kernels::kMixedCell);
  EXPECT_EQ(entry({3, 7, 7}), kernels::kMixedCell);
  EXPECT_EQ(entry({7, 3, 7}), kernels::kMixedCell);  // a later match does not undo a difference
  EXPECT_EQ(entry({0xfffeu, 0xfffeu}), 0xfffeu);
  EXPECT_EQ(entry({0xffffu}), kernels::kMixedCell);
  EXPECT_EQ(entry({0x10007u, 0x10007u}), kernels::kMixedCell);
}

// The clustered particles as three bodies: body 1 left of x = 0.5 m, body 2 right of it, every
// 13th particle body 3; the cells' entries as the GPU's grid writes them, empty cells' set to
// kMixedCell, as a stale entry may be.
SortedParticles three_bodies(std::mt19937_64& random) {
  SortedParticles sorted = clustered_particles(random, /*half_cells=*/true);
  for (std::size_t s = 0; s < sorted.position.size(); ++s) {
    const std::uint32_t body = s % 13 == 0 ? 3u : sorted.position[s].x < 0.5f ? 1u : 2u;
    sorted.position[s].w = kernels::index_as_float_bits(body);
  }
  sorted.note_cell_bodies(kernels::kMixedCell);
  return sorted;
}

// What the walks that leave out a body met.
struct LeftOutWalks {
  std::size_t rows_left_out = 0, rows_kept = 0;
};

// A walk around each point that leaves out each of `bodies` (and one that leaves out none) visits,
// lane by lane, what a full walk would over every range of expected_ranges but those whose
// particles all belong to the body left out; a body whose index no cell_body entry can name is
// never left out (its walks stay right, only longer: density_sum_over skips its own particles).
LeftOutWalks expect_walks_leave_out_rows(const SortedParticles& sorted, const std::vector<Vec3>& points,
                                         const std::vector<std::uint32_t>& bodies) {
  const kernels::CellRanges grid = sorted.grid();
  LeftOutWalks met;
  for (std::size_t q = 0; q < points.size(); ++q) {
    SCOPED_TRACE(::testing::Message() << "query " << q);
    const Vec3 x = points[q];
    std::vector<std::uint32_t> left_outs = bodies;
    left_outs.push_back(kernels::kNoBody);
    for (const std::uint32_t left_out : left_outs) {
      SCOPED_TRACE(::testing::Message() << "body left out " << left_out);
      // A range is left out by what its whole cells hold, trimmed halves included; one lane walks
      // the rest trimmed, a team's lanes whole.
      std::vector<std::vector<std::uint32_t>> kept, kept_whole;
      const std::vector<std::vector<std::uint32_t>> ranges = expected_ranges(sorted, x);
      const std::vector<std::vector<std::uint32_t>> whole = expected_ranges(sorted, x, /*trim=*/false);
      for (std::size_t r = 0; r < ranges.size(); ++r) {
        if (whole[r].empty()) continue;
        const bool only_left_out =
            left_out < kernels::kMixedCell && std::all_of(whole[r].begin(), whole[r].end(), [&](std::uint32_t t) {
              return kernels::body_of(sorted.position[t]) == left_out;
            });
        if (only_left_out) {
          ++met.rows_left_out;
        } else {
          kept.push_back(ranges[r]);
          kept_whole.push_back(whole[r]);
          if (left_out != kernels::kNoBody) ++met.rows_kept;
        }
      }
      for (const std::uint32_t lanes : {1u, 3u, 8u}) {
        for (std::uint32_t lane = 0; lane < lanes; ++lane) {
          std::vector<std::uint32_t> visits, expected;
          grid.for_each_candidate(
              x, lane, lanes, [&](std::uint32_t t) { visits.push_back(t); }, grid.cells_holding_only(x, left_out));
          for (const std::vector<std::uint32_t>& range : lanes == 1 ? kept : kept_whole) {
            for (std::size_t k = lane; k < range.size(); k += lanes) expected.push_back(range[k]);
          }
          EXPECT_EQ(visits, expected) << "lane " << lane << " of " << lanes;
          if (::testing::Test::HasFailure()) return met;
        }
      }
    }
  }
  return met;
}

TEST(GridWalk, LeavesOutTheRowsThatHoldNothingButTheBodyLeftOut) {
  std::mt19937_64 random(20261128);
  const SortedParticles sorted = three_bodies(random);
  const LeftOutWalks met = expect_walks_leave_out_rows(sorted, query_points(sorted, random), {1u, 2u, 3u});
  EXPECT_GT(met.rows_left_out, 100u);
  EXPECT_GT(met.rows_kept, 100u);
}

// CellRanges::cells_holding_only around each point, for each of `bodies` and kNoBody: bit
// 9 (dz + 1) + 3 (dy + 1) + dx + 1 is set exactly where the cell at (dx, dy, dz) from the point's
// holds no particle of another body (found by every particle's key, not through the cell table),
// and never for a body no entry can name; the masks of `shares` lanes, each checking every
// shares-th cell from its own, hold only their own cells' bits and join into the whole mask.
// Returns how many bits were set.
std::size_t expect_cell_masks(const SortedParticles& sorted, const std::vector<Vec3>& points,
                              const std::vector<std::uint32_t>& bodies) {
  const kernels::CellRanges grid = sorted.grid();
  const kernels::GridShape& shape = sorted.shape;
  std::size_t bits_set = 0;
  for (std::size_t q = 0; q < points.size(); ++q) {
    SCOPED_TRACE(::testing::Message() << "query " << q);
    const Vec3 x = points[q];
    int cx, cy, cz;
    shape.cell_of(x, cx, cy, cz);
    std::vector<std::uint32_t> left_outs = bodies;
    left_outs.push_back(kernels::kNoBody);
    for (const std::uint32_t body : left_outs) {
      SCOPED_TRACE(::testing::Message() << "body " << body);
      std::uint32_t expected = 0;
      for (std::uint32_t bit = 0; bit < 27; ++bit) {
        const std::uint32_t key = shape.key(cx + static_cast<int>(bit % 3) - 1, cy + static_cast<int>(bit / 3 % 3) - 1,
                                            cz + static_cast<int>(bit / 9) - 1);
        const bool only_body = std::all_of(sorted.position.begin(), sorted.position.end(), [&](const kernels::Vec4& p) {
          return shape.key_of(kernels::xyz(p)) != key || kernels::body_of(p) == body;
        });
        if (only_body && body < kernels::kMixedCell) expected |= 1u << bit;
      }
      const std::uint32_t whole = grid.cells_holding_only(x, body);
      EXPECT_EQ(whole, expected);
      bits_set += static_cast<std::size_t>(std::bitset<32>(whole).count());
      for (const std::uint32_t shares : {2u, 3u, 5u, 8u, 27u, 32u}) {
        std::uint32_t joined = 0;
        for (std::uint32_t share = 0; share < shares; ++share) {
          const std::uint32_t part = grid.cells_holding_only(x, body, share, shares);
          std::uint32_t own_bits = 0;
          for (std::uint32_t bit = share; bit < 32; bit += shares) own_bits |= 1u << bit;
          EXPECT_EQ(part & ~own_bits, 0u) << "share " << share << " of " << shares;
          joined |= part;
        }
        EXPECT_EQ(joined, whole) << shares << " shares";
      }
      if (::testing::Test::HasFailure()) return bits_set;
    }
  }
  return bits_set;
}

TEST(GridWalk, MarksTheCellsThatHoldNothingButABody) {
  std::mt19937_64 random(20261128);
  const SortedParticles sorted = three_bodies(random);
  EXPECT_GT(expect_cell_masks(sorted, query_points(sorted, random), {1u, 2u, 3u}), 1000u);
}

// A block of body 1 filling cells 0 to 7 on every axis of a 16^3 grid of 1 m cells (8 particles a
// cell), a slab of body 2 beside it along x (cells x = 8), two particles of body 2 inside the
// block, and particles of body 65535 (kMixedCell's value, which no entry can name) in the slab's
// cells and beside them, so that cells of bodies 2 and 65535 are mixed.
SortedParticles block_with_intruders() {
  std::vector<kernels::Vec4> particles;
  const auto add = [&](float x, float y, float z, std::uint32_t body) {
    particles.push_back(kernels::Vec4{x, y, z, kernels::index_as_float_bits(body)});
  };
  const auto lattice = [](int k) { return 0.25f + 0.5f * static_cast<float>(k); };  // 2 a cell, centred
  for (int i = 0; i < 16; ++i) {
    for (int j = 0; j < 16; ++j) {
      for (int k = 0; k < 16; ++k) add(lattice(i), lattice(j), lattice(k), 1u);
    }
  }
  for (int i = 16; i < 18; ++i) {
    for (int j = 0; j < 16; ++j) {
      for (int k = 0; k < 16; ++k) add(lattice(i), lattice(j), lattice(k), 2u);
    }
  }
  add(3.3f, 3.4f, 3.6f, 2u);
  add(6.1f, 1.2f, 5.5f, 2u);
  for (int j = 0; j < 4; ++j) {
    add(8.6f, lattice(j) + 0.15f, 0.6f, 0xffffu);
    add(9.4f, lattice(j) + 0.15f, 0.6f, 0xffffu);
  }
  SortedParticles sorted = sort_into_grid(particles, metre_cells(4, 4, 4));
  sorted.note_cell_bodies(kernels::kMixedCell);
  return sorted;
}

// In and around the block, beside its intruders, and for body 65535, whose neighbours share mixed
// cells (kMixedCell, the entry's value for that index too): a walk leaves out exactly the rows
// that hold nothing but a body an entry can name.
TEST(GridWalk, LeavesOutNoRowForABodyNoCellEntryCanName) {
  const SortedParticles sorted = block_with_intruders();
  std::mt19937_64 random(20261128);
  std::vector<Vec3> points;
  for (std::size_t s = 0; s < sorted.position.size(); ++s) {
    const kernels::Vec4& p = sorted.position[s];
    const bool intruder = kernels::body_of(p) == 0xffffu || (kernels::body_of(p) == 2u && p.x < 8.0f);
    if (intruder || s % 29 == 0) points.push_back(kernels::xyz(p));  // every intruder, every 29th of the rest
  }
  std::uniform_real_distribution<float> anywhere(-1.0f, 17.0f);
  for (int q = 0; q < 100; ++q) points.push_back(Vec3{anywhere(random), anywhere(random), anywhere(random)});
  const LeftOutWalks met = expect_walks_leave_out_rows(sorted, points, {1u, 2u, 0xffffu});
  EXPECT_GT(met.rows_left_out, 100u);
  EXPECT_GT(met.rows_kept, 100u);
}

// The same marks in and around the block with intruders, where whole rows hold one body.
TEST(GridWalk, MarksTheCellsOfOneBodyAroundABlockWithIntruders) {
  const SortedParticles sorted = block_with_intruders();
  std::vector<Vec3> points;
  for (std::size_t s = 0; s < sorted.position.size(); s += 37) points.push_back(kernels::xyz(sorted.position[s]));
  EXPECT_GT(expect_cell_masks(sorted, points, {1u, 2u, 0xffffu}), 1000u);
}

}  // namespace
}  // namespace mssph::testing
