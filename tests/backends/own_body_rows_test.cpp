// The density walks of rigid, deformable and boundary particles leave out the rows of cells that
// hold nothing but their own body (kernels/common/fluid_physics.hpp, body_left_out;
// CellRanges::cell_body), whose pairs add nothing to their sums. Checked on the neighbour-list
// tests' lattice, in a grid large enough for rows inside the block, with the block deformable and
// rigid: every particle's density sum (every team size's shares) and a team's lists, recorded by
// that walk, are the same, bit for bit, with the rows left out as without, and the block's walks
// do get shorter.
#include "common/fluid_physics.hpp"
#include "common/list_skin.hpp"
#include "neighbour_list_fixtures.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>

namespace mssph::testing {
namespace {

std::size_t walk_length(const kernels::SortedView& v, std::uint32_t s) {
  std::size_t visits = 0;
  kernels::grid_share(v, s, 0, 1, kernels::cells_left_out(v, s))([&](std::uint32_t) { ++visits; });
  return visits;
}

class OwnBodyRows : public ::testing::TestWithParam<std::uint32_t> {};

TEST_P(OwnBodyRows, LeavingThemOutChangesNoSumAndNoList) {
  std::mt19937_64 random(20261128);
  const float compression = compressed_by_up_to_4_percent(random);
  // 8 cells of side h per axis: the lattice spans 6, so the grid does not wrap and the block has
  // rows of its own.
  std::mt19937_64 jitter(random());
  const JitteredLattice all_rows(jitter, compression, 1.0f, GetParam(), 3);
  JitteredLattice own_rows_left_out = all_rows;
  own_rows_left_out.leave_out_own_rows();
  const kernels::SortedView full = all_rows.view(), leaving = own_rows_left_out.view();
  std::size_t shortened = 0;
  for (std::uint32_t s = 0; s < all_rows.size(); ++s) {
    SCOPED_TRACE(::testing::Message() << "particle " << s);
    const bool at_rest = kernels::takes_own_body_at_rest(full.bodies[kernels::body_of(full.position[s])]);
    const std::size_t full_walk = walk_length(full, s), shorter_walk = walk_length(leaving, s);
    ASSERT_TRUE(at_rest ? shorter_walk <= full_walk : shorter_walk == full_walk);
    if (shorter_walk < full_walk) ++shortened;
    for (const std::uint32_t lanes : {1u, 2u, 4u, 8u}) {
      for (std::uint32_t lane = 0; lane < lanes; ++lane) {
        const kernels::DensitySum a = kernels::density_sum(full, s, lane, lanes);
        const kernels::DensitySum b = kernels::density_sum(leaving, s, lane, lanes);
        ASSERT_TRUE(same_bits(a.delta, b.delta) && same_bits(a.nearest_other_body2, b.nearest_other_body2))
            << "lane " << lane << " of " << lanes;
      }
    }
  }
  EXPECT_GT(shortened, 100u);
  const float record_radius2 = kernels::list_skin(full.step.smoothing.h).record_radius2;
  const std::uint32_t capacity = 64;  // room for every list: none overflows into a walk
  for (const std::uint32_t lanes : {2u, 4u, 8u}) {
    const TeamLists a(full, lanes, capacity, record_radius2), b(leaving, lanes, capacity, record_radius2);
    EXPECT_EQ(a.count, b.count) << lanes << " lanes";
    EXPECT_EQ(a.index, b.index) << lanes << " lanes";
    EXPECT_EQ(a.density, b.density) << lanes << " lanes";
  }
}

INSTANTIATE_TEST_SUITE_P(BlockKinds, OwnBodyRows, ::testing::Values(kernels::kDeformable, kernels::kRigid),
                         [](const ::testing::TestParamInfo<std::uint32_t>& kind) {
                           return kind.param == kernels::kRigid ? std::string("rigid") : std::string("deformable");
                         });

}  // namespace
}  // namespace mssph::testing
