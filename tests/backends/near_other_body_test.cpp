// The force pass skips the walk of a rigid or deformable particle whose density sum met no other
// body within h (kernels/common/fluid_physics.hpp, may_feel_forces). Both halves of that are
// checked on the neighbour-list tests' lattice (walls, fluid, a deformable or rigid block): the
// density sum's nearest other body, from every team size's shares, against a brute-force search
// over all particles, and from a rebuild's shares, which record the teams' lists and sum over
// them (density_sum_recording, its lists roomy or overflowed); and, for every particle the note
// lets skip, the force sums of the full walk, which must be zero, so skipping changes nothing.
#include "common/fluid_physics.hpp"
#include "common/list_skin.hpp"
#include "neighbour_list_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace mssph::testing {
namespace {

bool brute_force_near_other_body(const kernels::SortedView& v, std::uint32_t s) {
  for (std::uint32_t t = 0; t < v.step.particle_count; ++t) {
    if (kernels::body_of(v.position[t]) != kernels::body_of(v.position[s]) && within_support(v, s, t)) return true;
  }
  return false;
}

bool is_zero(Vec3 a) { return a.x == 0.0f && a.y == 0.0f && a.z == 0.0f; }

// The lattice's block as a deformable body (its density sum skips its own particles) and as a
// rigid one (its density sum takes them all).
class NearOtherBody : public ::testing::TestWithParam<std::uint32_t> {};

TEST_P(NearOtherBody, TheDensitySumNotesAnotherBodyWithinHAndWithoutOneTheForceSumsAreZero) {
  std::mt19937_64 random(20261127);
  const JitteredLattice lattice(random, compressed_by_up_to_4_percent(random), 1.0f, GetParam());
  const kernels::SortedView v = lattice.view();
  const float record_radius2 = kernels::list_skin(v.step.smoothing.h).record_radius2;
  std::vector<TeamLists> rebuilds;
  rebuilds.reserve(6);  // each one's lists point into its own arrays
  for (const std::uint32_t lanes : {2u, 4u, 8u}) {
    for (const std::uint32_t capacity : {64u, 2u}) rebuilds.emplace_back(v, lanes, capacity, record_radius2);
  }
  std::size_t skipped = 0, block_near_another = 0;
  for (std::uint32_t s = 0; s < lattice.size(); ++s) {
    SCOPED_TRACE(::testing::Message() << "particle " << s);
    const kernels::ForceParticle i = kernels::load_force_particle(v, s);
    if (i.body != kDeformableBody) {  // walls and fluid: never skipped, whatever their neighbours
      ASSERT_TRUE(i.parameters.kind == kernels::kBoundary || kernels::may_feel_forces(i.parameters, false));
      continue;
    }
    const bool expected = brute_force_near_other_body(v, s);
    for (const std::uint32_t lanes : {1u, 2u, 4u, 8u}) {
      float nearest2 = std::numeric_limits<float>::infinity();
      for (std::uint32_t lane = 0; lane < lanes; ++lane) {
        nearest2 = std::fmin(nearest2, kernels::density_sum(v, s, lane, lanes).nearest_other_body2);
      }
      ASSERT_EQ(nearest2 < v.step.smoothing.h2, expected) << lanes << " lanes";
    }
    for (const TeamLists& rebuild : rebuilds) {
      float nearest2 = std::numeric_limits<float>::infinity();
      for (std::uint32_t lane = 0; lane < rebuild.lanes; ++lane) {
        nearest2 = std::fmin(nearest2, rebuild.nearest_other_body2[rebuild.list_of(s, lane)]);
      }
      ASSERT_EQ(nearest2 < v.step.smoothing.h2, expected)
          << rebuild.lanes << " lanes recording lists of capacity " << rebuild.lists.capacity;
    }
    if (expected) ++block_near_another;
    if (kernels::may_feel_forces(i.parameters, expected)) continue;
    ++skipped;
    const kernels::ForceSum walked = kernels::force_sum(v, i);
    ASSERT_TRUE(is_zero(walked.pressure) && is_zero(walked.viscosity) && is_zero(walked.interaction));
    ASSERT_EQ(walked.nearest_boundary2, kernels::zero_force_sum().nearest_boundary2);
  }
  // The block has an inside to skip and a surface that touches the fluid and the walls.
  EXPECT_GT(skipped, 100u);
  EXPECT_GT(block_near_another, 100u);
}

INSTANTIATE_TEST_SUITE_P(BlockKinds, NearOtherBody, ::testing::Values(kernels::kDeformable, kernels::kRigid),
                         [](const ::testing::TestParamInfo<std::uint32_t>& kind) {
                           return kind.param == kernels::kRigid ? std::string("rigid") : std::string("deformable");
                         });

}  // namespace
}  // namespace mssph::testing
