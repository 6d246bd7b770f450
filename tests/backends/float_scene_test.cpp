// The float scene keeps the own-body number density at rest (model/deformable_rest_state.hpp) of
// every particle that takes its own body at rest (kernels/common/fluid_physics.hpp,
// takes_own_body_at_rest), once, and none of a fluid particle's: checked on the fluid drop (fluid,
// a container's walls, a rigid sphere) and the deformable drop (no fluid) against the rest state
// it comes from, each read where the kernels read it (number_density_of: the canonical index less
// the body's own_rest_offset); and the rest state's own-body neighbourhoods against brute force.
#include "common/float_scene.hpp"
#include "backend_fixtures.hpp"
#include "common/fluid_physics.hpp"
#include "model/deformable_rest_state.hpp"
#include "model/smoothing_kernels.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace mssph::testing {
namespace {

class FloatSceneRestShares : public ::testing::TestWithParam<std::string> {};

TEST_P(FloatSceneRestShares, EachParticleAtRestFindsItsOwnShareAndFluidHoldsNone) {
  const ParticleSetup setup = coarse_scene(GetParam(), 0.01);
  const kernels::FloatScene scene = kernels::make_float_scene(setup);
  const DeformableRestState rest = build_deformable_rest_state(setup);
  std::array<std::size_t, 4> particles_of_kind{};
  for (std::size_t i = 0; i < setup.size(); ++i) {
    SCOPED_TRACE(::testing::Message() << "particle " << i);
    const kernels::BodyParameters& body = scene.bodies[scene.body[i]];
    ++particles_of_kind[body.kind];
    if (!kernels::takes_own_body_at_rest(body)) continue;
    const std::size_t entry = i - body.own_rest_offset;
    ASSERT_LT(entry, scene.own_rest_number_density.size());
    EXPECT_GT(rest.own_rest_number_density[i], 0.0);
    EXPECT_EQ(scene.own_rest_number_density[entry], static_cast<float>(rest.own_rest_number_density[i]));
  }
  EXPECT_GT(particles_of_kind[kernels::kBoundary], 0u);
  EXPECT_EQ(scene.own_rest_number_density.size(), setup.size() - particles_of_kind[kernels::kFluid]);
}

// The rest state's own-body neighbourhoods against a brute-force search of each body: a deformable
// particle's rest neighbours are its body's other particles within h, and the own-body number density
// at rest of a rigid, deformable or boundary particle is W(0) plus W over them; a fluid particle has
// neither.
TEST_P(FloatSceneRestShares, OwnBodyNeighbourhoodsAreThoseABruteForceSearchFinds) {
  const ParticleSetup setup = coarse_scene(GetParam(), 0.01);
  const DeformableRestState rest = build_deformable_rest_state(setup);
  const double h = setup.smoothing_length;
  const SpikyKernel w(h);
  for (std::size_t i = 0; i < setup.size(); ++i) {
    SCOPED_TRACE(::testing::Message() << "particle " << i);
    std::vector<std::size_t> within;
    double delta = w(0.0);
    for (std::size_t j = 0; j < setup.size(); ++j) {
      if (j == i || setup.body[j] != setup.body[i]) continue;
      const double r = (setup.position[j] - setup.position[i]).norm();
      if (r >= h) continue;
      within.push_back(j);
      delta += w(r);
    }
    const BodyKind kind = setup.bodies[setup.body[i]].kind;
    std::vector<std::size_t> listed(rest.neighbours.begin(i), rest.neighbours.end(i));
    std::sort(listed.begin(), listed.end());
    EXPECT_EQ(listed, kind == BodyKind::deformable ? within : std::vector<std::size_t>{});
    EXPECT_NEAR(rest.own_rest_number_density[i], has_own_rest_number_density(kind) ? delta : 0.0, 1e-12 * delta);
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, FloatSceneRestShares,
                         ::testing::Values("sphere_drop_fluid.json", "sphere_drop_deformable.json"),
                         [](const ::testing::TestParamInfo<std::string>& scene) {
                           return scene.param == "sphere_drop_fluid.json" ? std::string("fluid_drop")
                                                                          : std::string("deformable_drop");
                         });

}  // namespace
}  // namespace mssph::testing
