// The held-neighbour walk of the GPU force sum (kernels/common/held_neighbours.hpp): a lane holds
// the candidates within the support in a column of capacity entries and visits them when it fills
// and at the end. Its sums are bit-identical to the plain walk's only if it visits exactly the
// plain walk's in-support candidates, in the plain walk's order, for every team size and every
// capacity, whether the column fills once, many times or never; and it must write nowhere but its
// column's entries. The expectation filters the plain walk (CellRanges::for_each_candidate, checked
// against brute force in grid_walk_test) by the distance, outside the function under test.
#include "common/held_neighbours.hpp"
#include "sorted_particles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace mssph::testing {
namespace {

using kernels::Vec3;

kernels::SortedView view_of(const SortedParticles& sorted) {
  kernels::SortedView v{};
  v.step.smoothing = kernels::SmoothingKernels::for_support(1.0);
  v.grid = sorted.grid();
  v.position = sorted.position.data();
  return v;
}

// Lane `lane`'s in-support candidates in the plain walk's order.
std::vector<std::uint32_t> expected_neighbours(const kernels::SortedView& v, Vec3 x, std::uint32_t lane,
                                               std::uint32_t lanes) {
  std::vector<std::uint32_t> expected;
  v.grid.for_each_candidate(x, lane, lanes, [&](std::uint32_t t) {
    if (kernels::squared_norm(x - kernels::xyz(v.position[t])) < v.step.smoothing.h2) expected.push_back(t);
  });
  return expected;
}

TEST(HeldNeighbours, VisitsThePlainWalksNeighboursInItsOrderWhateverTheCapacity) {
  std::mt19937_64 random(20261125);
  const SortedParticles sorted = clustered_particles(random);
  const kernels::SortedView v = view_of(sorted);
  std::uniform_real_distribution<float> query(-3.0f, 4.0f);
  constexpr std::uint32_t kUntouched = 0xdeadbeefu;
  constexpr std::uint32_t kStride = 3;  // columns interleaved as in the GPU's shared memory
  std::size_t most_neighbours = 0, walks_without_neighbours = 0;
  for (int q = 0; q < 120; ++q) {
    SCOPED_TRACE(::testing::Message() << "query " << q);
    const Vec3 x = q < 60 ? kernels::xyz(sorted.position[q * 11]) : Vec3{query(random), query(random), query(random)};
    for (const std::uint32_t lanes : {1u, 2u, 4u, 8u}) {
      for (std::uint32_t lane = 0; lane < lanes; ++lane) {
        const std::vector<std::uint32_t> expected = expected_neighbours(v, x, lane, lanes);
        most_neighbours = std::max(most_neighbours, expected.size());
        if (expected.empty()) ++walks_without_neighbours;
        for (const std::uint32_t capacity : {1u, 2u, 3u, 11u, 64u}) {
          SCOPED_TRACE(::testing::Message() << lanes << " lanes, lane " << lane << ", capacity " << capacity);
          // The column plus one more row: every word but entry k's (k < capacity) must stay untouched.
          std::vector<std::uint32_t> buffer((capacity + 1) * kStride, kUntouched);
          std::vector<std::uint32_t> visits;
          kernels::for_each_held_neighbour(v, x, lane, lanes, kernels::HeldColumn{buffer.data() + 1, kStride, capacity},
                                           [&](std::uint32_t t) { visits.push_back(t); });
          ASSERT_EQ(visits, expected);
          for (std::size_t word = 0; word < buffer.size(); ++word) {
            const bool entry = word >= 1 && (word - 1) % kStride == 0 && (word - 1) / kStride < capacity;
            if (!entry) {
              ASSERT_EQ(buffer[word], kUntouched) << "word " << word;
            }
          }
        }
      }
    }
  }
  // The corner cases were met: a lane's neighbours filled the largest column more than once, and
  // some lanes had none.
  EXPECT_GT(most_neighbours, 2u * 64u);
  EXPECT_GT(walks_without_neighbours, 0u);
}

}  // namespace
}  // namespace mssph::testing
