// The float backends' neighbour lists with a skin (kernels/common/list_skin.hpp): the cpu
// backend's, and the cuda backend's teams' on the GPU. In the fluid sphere drop the grid is rebuilt
// on some steps and kept on the others, and a step that kept the lists finds the densities a fresh
// grid gives where the particles stand, there and in the rigid drop, whose falling sphere, the only
// body that moves, has a trigger of its own; in both, no step keeps the lists once a particle has
// moved past its trigger. (list_skin_test.cpp checks the lists' neighbours themselves, up to the
// moment a pair crosses the skin.)
#include "backend_fixtures.hpp"
#include "common/float_scene.hpp"
#include "common/list_skin.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace mssph::testing {
namespace {

constexpr int kSteps = 400;        // 0.1 s: the sphere falls onto the fluid and sinks in
constexpr int kFirstChecked = 40;  // the first step checked: the sphere is falling by then

// Steps `backend` k times.
void step(Backend& backend, int k) {
  for (int i = 0; i < k; ++i) backend.step();
}

class SkinLists : public ::testing::TestWithParam<std::string> {};

TEST_P(SkinLists, TheGridIsRebuiltOnSomeStepsAndKeptOnOthers) {
  MSSPH_SKIP_WITHOUT(GetParam());
  const ParticleSetup setup = coarse_scene("sphere_drop_fluid.json", kSteps * 0.00025);
  const std::unique_ptr<Backend> backend = make_backend(GetParam(), setup);
  ASSERT_TRUE(backend->neighbour_grid_builds().has_value()) << "a scene this small keeps lists";
  step(*backend, kSteps);
  const std::uint64_t builds = *backend->neighbour_grid_builds();
  EXPECT_GT(builds, 1u) << "the falling sphere's move ends the lists";
  EXPECT_LT(builds, static_cast<std::uint64_t>(kSteps) / 2) << "the resting fluid keeps its lists";
}

// The densities of every step k from kFirstChecked to kLastChecked that kept the lists against
// those of a fresh grid at the same positions: a second backend restored from the first's state
// before step k (restarts are exact: the positions are compared) whose evaluate_forces() rebuilds
// the grid before its density pass. The two sums take the same terms in other orders, so they
// agree to float rounding. A neighbour missing from the lists at 0.9 h would move its particle's
// density by about 6e-4 of it (spiky W(0.9 h) against the rest number density at h = 2 dx), 60
// times the tolerance; one missing nearer h moves it by less (W falls as (h - r)^3), which the
// host test of the lists' sets covers. The test fails, on a GPU and on the host, with the skin
// taken away (lists recorded within h) or with moved_past_trigger taken away (no rebuild after the
// first); in the rigid drop, also when a particle reads another body's trigger (the sphere's
// particles a wall's, zero: a rebuild every step, so no step to check).
TEST_P(SkinLists, AStepThatKeepsTheListsHasTheDensitiesOfAFreshGrid) {
  MSSPH_SKIP_WITHOUT(GetParam());
  constexpr int kLastChecked = 200;
  for (const char* config : {"sphere_drop_fluid.json", "sphere_drop_rigid.json"}) {
    SCOPED_TRACE(config);
    const ParticleSetup setup = coarse_scene(config, kSteps * 0.00025);
    const std::unique_ptr<Backend> listed = make_backend(GetParam(), setup);
    step(*listed, kFirstChecked - 1);
    int checked = 0;
    for (int k = kFirstChecked; k <= kLastChecked; ++k) {
      const std::uint64_t builds_before = *listed->neighbour_grid_builds();
      const StateArrays before = listed->save_state();
      const std::vector<float> positions_before = listed->snapshot().position;
      listed->step();
      if (*listed->neighbour_grid_builds() != builds_before) continue;  // step k rebuilt the grid
      SCOPED_TRACE(::testing::Message() << "step " << k);
      const std::unique_ptr<Backend> fresh = make_backend(GetParam(), setup);
      fresh->restore_state(before);
      ASSERT_EQ(fresh->snapshot().position, positions_before) << "the second backend stands where the first stood";
      const ForceEvaluation fresh_grid = fresh->evaluate_forces();
      const ParticleSnapshot from_lists = listed->snapshot();
      ASSERT_EQ(from_lists.density.size(), fresh_grid.density.size());
      for (std::size_t i = 0; i < fresh_grid.density.size(); ++i) {
        ASSERT_NEAR(from_lists.density[i], fresh_grid.density[i], 1e-5 * fresh_grid.density[i]) << "particle " << i;
      }
      ++checked;
    }
    EXPECT_GT(checked, (kLastChecked - kFirstChecked) / 2) << "steps that kept the lists";
  }
}

// The lists are kept only while they hold: at the start of every step that kept them, each particle
// stands within its body's trigger of where it stood at the start of the last step that rebuilt
// (moved_past_trigger, list_triggers2), in the backend's own float positions (save_state). In the
// fluid drop the fluid moves, which the GPU checks where its force pass advances the particles; in
// the rigid drop only the sphere, which the GPU checks where its rigid-body pass places them
// (kernels/cuda/list_check.cuh). The test fails on the GPU when that placement never flags a move.
TEST_P(SkinLists, ListsAreKeptOnlyWhileEveryParticleIsWithinItsTrigger) {
  MSSPH_SKIP_WITHOUT(GetParam());
  for (const char* config : {"sphere_drop_fluid.json", "sphere_drop_rigid.json"}) {
    SCOPED_TRACE(config);
    const ParticleSetup setup = coarse_scene(config, kSteps * 0.00025);
    const kernels::FloatScene scene = kernels::make_float_scene_with_list_cells(setup);
    const std::unique_ptr<Backend> backend = make_backend(GetParam(), setup);
    const auto at = [](const std::vector<float>& position, std::size_t i) {
      return kernels::Vec3{position[4 * i], position[4 * i + 1], position[4 * i + 2]};
    };
    std::vector<float> origin;
    int kept = 0;
    for (int k = 0; k < kSteps; ++k) {
      const std::vector<float> start = backend->save_state().get<float>("position", 4 * setup.size());
      const std::uint64_t builds_before = *backend->neighbour_grid_builds();
      backend->step();
      if (*backend->neighbour_grid_builds() != builds_before) {
        origin = start;
        continue;
      }
      ASSERT_FALSE(origin.empty()) << "the first step rebuilds";
      ++kept;
      for (std::size_t i = 0; i < setup.size(); ++i) {
        ASSERT_FALSE(kernels::moved_past_trigger(at(start, i), at(origin, i), scene.list_trigger2[scene.body[i]]))
            << "step " << k << " kept the lists, though particle " << i << " had moved past its trigger";
      }
    }
    EXPECT_GT(kept, kSteps / 2) << "steps that kept the lists";
  }
}

INSTANTIATE_TEST_SUITE_P(FloatBackends, SkinLists, ::testing::ValuesIn(float_backend_names()),
                         [](const auto& test) { return test.param; });

}  // namespace
}  // namespace mssph::testing
