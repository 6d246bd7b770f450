// The cuda backend replays each step as one captured graph (kernels/cuda/cuda_backend.cu); its
// size, which a step's launch floor scales with, is what `mssph bench` reports beside the time.
// The host backends run a step as code and report none.
#include "backend_fixtures.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace mssph::testing {
namespace {

// The deformable drop gives every phase work: the grid, the rotations and elastic forces, the
// densities, the forces and the rigid sphere's dynamics. The fluid drop has no deformable body,
// so its step leaves out the rotation and elastic kernels.
ParticleSetup every_phase_scene() { return coarse_scene("sphere_drop_deformable.json", 0.01); }
ParticleSetup no_deformable_scene() { return coarse_scene("sphere_drop_fluid.json", 0.01); }

TEST(StepGraph, CudaStepHoldsAKernelForEachPhaseAndOnlyThePassesItsSceneNeeds) {
  MSSPH_SKIP_WITHOUT("cuda");
  const std::optional<Backend::StepGraphSize> every = make_backend("cuda", every_phase_scene())->step_graph_size();
  const std::optional<Backend::StepGraphSize> fewer = make_backend("cuda", no_deformable_scene())->step_graph_size();
  ASSERT_TRUE(every.has_value());
  ASSERT_TRUE(fewer.has_value());
  EXPECT_GE(every->kernels, static_cast<std::size_t>(Backend::kPhaseCount));
  EXPECT_LT(fewer->kernels, every->kernels);
  EXPECT_LT(fewer->nodes, every->nodes);
}

TEST(StepGraph, HostBackendsReportNone) {
  const ParticleSetup setup = every_phase_scene();
  for (const std::string name : {"cpu", "reference"}) {
    EXPECT_FALSE(make_backend(name, setup)->step_graph_size().has_value()) << name;
  }
}

}  // namespace
}  // namespace mssph::testing
