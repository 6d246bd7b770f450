// The force pass's seats (kernels/cuda/contact_order.hpp): after the density pass's records, the
// teams of the force pass serve every particle exactly once, and walk exactly where
// may_feel_forces says, whatever the contact order's capacity: a place for every block particle
// (some stay empty), a quarter of them (the one-lane scenes'), room for one place (every walking
// particle but one overflows into cell order), or none (teams). The places are handed out in a shuffled order, as the
// GPU's warps take them in whatever order they reach the atomic add.
#include "cuda/contact_order.hpp"
#include "common/fluid_physics.hpp"
#include "neighbour_list_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace mssph::testing {
namespace {

// The density pass's records for the view, one lane a particle, with a contact order of
// `capacity` places; `near[s]`: whether another body lies within h of sorted particle s.
struct DensityPassRecords {
  std::vector<std::uint8_t> walk;
  std::vector<std::uint32_t> order;
  std::uint32_t taken = 0;

  DensityPassRecords(const kernels::SortedView& v, const std::vector<bool>& near, std::uint32_t capacity,
                     std::mt19937_64& random)
      : walk(v.step.particle_count), order(capacity) {
    std::vector<std::uint32_t> asking;
    for (std::uint32_t s = 0; s < v.step.particle_count; ++s) {
      if (kernels::asks_contact_place(v.bodies[kernels::body_of(v.position[s])], near[s])) asking.push_back(s);
    }
    std::shuffle(asking.begin(), asking.end(), random);
    std::vector<std::uint32_t> place(v.step.particle_count, capacity);
    for (const std::uint32_t s : asking) place[s] = std::min(taken++, capacity);
    for (std::uint32_t s = 0; s < v.step.particle_count; ++s) {
      walk[s] = kernels::force_walk_of(near[s], place[s], capacity);
      if (place[s] < capacity) order[place[s]] = s;
    }
  }
  kernels::ForceWalks walks() { return {walk.data(), order.data(), &taken, static_cast<std::uint32_t>(order.size())}; }
};

class ForceSeats : public ::testing::TestWithParam<std::uint32_t> {};

TEST_P(ForceSeats, ServeEveryParticleOnceAndWalkWhereItMayFeelForces) {
  std::mt19937_64 random(20261202);
  const JitteredLattice lattice(random, 1.0f, 1.0f, GetParam());
  const kernels::SortedView v = lattice.view();
  const std::uint32_t n = lattice.size();
  std::vector<bool> near(n);
  std::uint32_t block = 0;
  for (std::uint32_t s = 0; s < n; ++s) {
    near[s] = kernels::density_sum(v, s, 0, 1).nearest_other_body2 < v.step.smoothing.h2;
    if (kernels::body_of(v.position[s]) == kDeformableBody) ++block;
  }
  for (const std::uint32_t capacity : {block, (block + 3) / 4, 1u, 0u}) {
    SCOPED_TRACE(::testing::Message() << "capacity " << capacity);
    DensityPassRecords records(v, near, capacity, random);
    const kernels::ForceWalks walks = records.walks();
    std::vector<int> served(n, 0);
    std::uint32_t from_order = 0;
    for (std::uint32_t member = 0; member < n + capacity; ++member) {
      const kernels::ForceSeat seat = kernels::force_seat(v, walks, member);
      if (!seat.active) continue;
      ASSERT_LT(seat.s, n);
      ++served[seat.s];
      if (member >= n) ++from_order;
      const kernels::BodyParameters& body = v.bodies[kernels::body_of(v.position[seat.s])];
      ASSERT_EQ(seat.walks, kernels::may_feel_forces(body, near[seat.s])) << "particle " << seat.s;
    }
    for (std::uint32_t s = 0; s < n; ++s) ASSERT_EQ(served[s], 1) << "particle " << s;
    // The block's surface asks for more places than one and fewer than the block's: the room for
    // one overflows, the room for all is left partly empty, and the order serves exactly the
    // places taken.
    ASSERT_GT(records.taken, 1u);
    ASSERT_LT(records.taken, block);
    EXPECT_EQ(from_order, std::min(records.taken, capacity));
  }
}

INSTANTIATE_TEST_SUITE_P(RigidAndDeformableBlocks, ForceSeats, ::testing::Values(kernels::kRigid, kernels::kDeformable),
                         [](const auto& test_info) {
                           return test_info.param == kernels::kRigid ? "rigid" : "deformable";
                         });

}  // namespace
}  // namespace mssph::testing
