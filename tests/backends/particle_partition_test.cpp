// The host's cost-balanced split of its particle loops (kernels/cpu/particle_partition.hpp): the
// parts cover every particle once, in order; each holds its share of the cost within one
// particle's; and its loop visits every particle once, also where the parallel region has fewer
// threads than there are parts.
#include "cpu/particle_partition.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <random>
#include <vector>

namespace mssph::testing {
namespace {

using kernels::ParticlePartition;

std::uint64_t cost_of_part(const ParticlePartition& partition, std::uint32_t part,
                           const std::vector<std::uint32_t>& cost) {
  std::uint64_t sum = 0;
  for (std::uint32_t s = partition.begin(part); s < partition.end(part); ++s) sum += cost[s];
  return sum;
}

// Costs like a container's: lists of 30-45 entries below, walls of cost 4 (no sum) above.
std::vector<std::uint32_t> fluid_below_walls(std::mt19937& random, std::uint32_t n) {
  std::uniform_int_distribution<std::uint32_t> list(30, 45);
  std::vector<std::uint32_t> cost(n, 4u);
  for (std::uint32_t s = 0; s < n * 2 / 3; ++s) cost[s] += list(random);
  return cost;
}

TEST(ParticlePartition, PartsCoverEveryParticleInOrderWithTheirShareOfTheCost) {
  std::mt19937 random(7);
  for (const std::uint32_t n : {0u, 1u, 5u, 1000u, 46188u}) {
    const std::vector<std::uint32_t> cost = fluid_below_walls(random, n);
    std::uint64_t total = 0;
    for (const std::uint32_t c : cost) total += c;
    const std::uint32_t largest = n == 0 ? 0u : *std::max_element(cost.begin(), cost.end());
    for (std::uint32_t parts = 1; parts <= 7; ++parts) {
      ParticlePartition partition;
      partition.assign(n, parts, [&](std::uint32_t s) { return cost[s]; });
      ASSERT_EQ(partition.parts(), parts);
      EXPECT_EQ(partition.begin(0), 0u);
      EXPECT_EQ(partition.end(parts - 1), n);
      for (std::uint32_t part = 0; part < parts; ++part) {
        SCOPED_TRACE(::testing::Message() << "n " << n << ", part " << part << " of " << parts);
        EXPECT_LE(partition.begin(part), partition.end(part));
        if (part + 1 < parts) {
          EXPECT_EQ(partition.end(part), partition.begin(part + 1));
        }
        // Share: total / parts, exceeded by at most the particle that reached it.
        EXPECT_LE(cost_of_part(partition, part, cost) * parts, total + std::uint64_t{largest} * parts);
      }
    }
  }
}

// Where the cost sits in the first half, two parts split that half: a split by particle count
// (OpenMP's static schedule) would give the second thread nothing to do.
TEST(ParticlePartition, SplitsWhereTheCostIsNotWhereTheParticlesAre) {
  const std::uint32_t n = 1000;
  std::vector<std::uint32_t> cost(n, 0u);
  std::fill(cost.begin(), cost.begin() + n / 2, 1u);
  ParticlePartition partition;
  partition.assign(n, 2, [&](std::uint32_t s) { return cost[s]; });
  EXPECT_EQ(partition.end(0), n / 4);
}

TEST(ParticlePartition, LoopVisitsEveryParticleOnceWithAsManyThreadsAsParts) {
  const std::uint32_t n = 10007;
  std::mt19937 random(11);
  const std::vector<std::uint32_t> cost = fluid_below_walls(random, n);
  for (std::uint32_t parts = 1; parts <= 4; ++parts) {
    ParticlePartition partition;
    partition.assign(n, parts, [&](std::uint32_t s) { return cost[s]; });
    std::vector<int> visits(n, 0);
    partition.for_each([&](std::uint32_t s) { ++visits[s]; });  // each s in one part: no race
    EXPECT_EQ(std::count(visits.begin(), visits.end(), 1), static_cast<long>(n)) << parts << " parts";
  }
}

// With no parallel region allowed to be active (max-active-levels 0, as in a region nested in one
// without nesting), the loop's region has one thread, which must take all five parts.
TEST(ParticlePartition, LoopVisitsEveryParticleOnceWithFewerThreadsThanParts) {
  const std::uint32_t n = 5000;
  ParticlePartition partition;
  partition.assign(n, 5, [](std::uint32_t) { return 1u; });
  std::vector<int> visits(n, 0);
  std::atomic<int> team_size{0};  // atomic: were the setting ignored, several threads would store it
  const int levels = omp_get_max_active_levels();
  omp_set_max_active_levels(0);
  partition.for_each([&](std::uint32_t s) {
    ++visits[s];
    team_size = omp_get_num_threads();
  });
  omp_set_max_active_levels(levels);
  EXPECT_EQ(team_size.load(), 1);
  EXPECT_EQ(std::count(visits.begin(), visits.end(), 1), static_cast<long>(n));
}

}  // namespace
}  // namespace mssph::testing
