// The shear-wave case (validation/physics/shear_decay) on the reference backend: the paper's
// eq. 3 gives the block the scene's viscosity, and the check sees a viscosity that is not.
#include "physics/shear_decay/shear_decay.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mssph::testing {
namespace {

// The case's coarsest block, 10 spacings: the wave decays at the rate of the scene's 20 Pa s
// within the case's 10 %, and its profile follows Stokes' series.
TEST(ShearDecay, BlockDecaysAtTheScenesViscosity) {
  const validation::ShearDecayMeasurement m =
      validation::measure_shear_decay("reference", validation::shear_decay_scene(0.04, 20.0, 0.5));
  EXPECT_NEAR(m.effective_viscosity, 20.0, 2.0);
  EXPECT_LT(m.profile_error, 0.10);
  EXPECT_NEAR(m.decay, std::exp(-0.5), 0.05);  // half a decay time at the scene's viscosity
}

// The planted error: the scene's fluid at half the viscosity the check expects decays at half
// the rate, which the case's 10 % rejects.
TEST(ShearDecay, HalvedViscosityIsSeen) {
  const validation::ShearDecayMeasurement m =
      validation::measure_shear_decay("reference", validation::shear_decay_scene(0.04, 10.0, 0.25));
  EXPECT_GT(std::abs(m.effective_viscosity / 20.0 - 1.0), 0.10);
}

}  // namespace
}  // namespace mssph::testing
