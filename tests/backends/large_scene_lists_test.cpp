// simulation/neighbour_lists: always on the cuda backend (kernels/common/team_lanes.hpp). The 1M
// rigid block (1.16M particles with its container) lies beyond four waves of a GPU's resident
// threads at two lanes a particle (on GPUs of up to 282 multiprocessors), where the size rule walks
// the grid with one lane every step; asked for, the lists come at that size too, the grid is kept
// between steps, and the densities agree with the walk's to float rounding (the same pairs summed
// in another order).
#include "backend_fixtures.hpp"
#include "model/block_scene.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>

namespace mssph::testing {
namespace {

constexpr int kListedSteps = 20;

TEST(LargeSceneLists, TheCudaBackendKeepsListsAtAnySizeWhenTheSceneAsksForThem) {
  MSSPH_SKIP_WITHOUT("cuda");
  Scene scene = block_scene(BodyKind::rigid, 1'000'000);
  const std::unique_ptr<Backend> walked = make_backend("cuda", build_particles(scene));
  scene.simulation.neighbour_lists = NeighbourListUse::always;
  const std::unique_ptr<Backend> listed = make_backend("cuda", build_particles(scene));
  if (walked->neighbour_grid_builds().has_value()) {
    GTEST_SKIP() << "this GPU holds the block within four waves: the size rule gives it lists already";
  }
  ASSERT_TRUE(listed->neighbour_grid_builds().has_value()) << "asked for, the lists come at any size";
  for (int k = 0; k < kListedSteps; ++k) {
    walked->step();
    listed->step();
  }
  EXPECT_LT(*listed->neighbour_grid_builds(), static_cast<std::uint64_t>(kListedSteps))
      << "the resting block keeps its grid between steps";
  const ParticleSnapshot by_walk = walked->snapshot();
  const ParticleSnapshot by_lists = listed->snapshot();
  ASSERT_EQ(by_walk.density.size(), by_lists.density.size());
  for (std::size_t i = 0; i < by_walk.density.size(); ++i) {
    ASSERT_NEAR(by_lists.density[i], by_walk.density[i], 1e-5 * by_walk.density[i]) << "particle " << i;
  }
}

}  // namespace
}  // namespace mssph::testing
