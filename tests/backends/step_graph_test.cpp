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
// densities, the forces and the rigid sphere's dynamics.
ParticleSetup every_phase_scene() { return coarse_scene("sphere_drop_deformable.json", 0.01); }

TEST(StepGraph, CudaStepHoldsAKernelForEachPhaseAtLeast) {
  MSSPH_SKIP_WITHOUT("cuda");
  const std::unique_ptr<Backend> backend = make_backend("cuda", every_phase_scene());
  const std::optional<Backend::StepGraphSize> size = backend->step_graph_size();
  ASSERT_TRUE(size.has_value());
  EXPECT_GE(size->kernels, static_cast<std::size_t>(Backend::kPhaseCount));
  EXPECT_GE(size->nodes, size->kernels);
}

TEST(StepGraph, HostBackendsReportNone) {
  const ParticleSetup setup = every_phase_scene();
  for (const std::string name : {"cpu", "reference"}) {
    EXPECT_FALSE(make_backend(name, setup)->step_graph_size().has_value()) << name;
  }
}

}  // namespace
}  // namespace mssph::testing
