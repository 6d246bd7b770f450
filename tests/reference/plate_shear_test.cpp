// The plate-drag case (validation/physics/plate_shear) on the reference backend: the viscosity
// between bodies (paper eq. 7) drags the fluid with Stokes' wall shear, and a free-slip plate
// (the planted error: its viscosity zero, so the interface viscosity is zero) feels none.
#include "physics/plate_shear/plate_shear.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mssph::testing {
namespace {

// The layer at 10 spacings (coarser than the case's 20, for the suite's time), 10 Pa s: within
// the case's 10 %.
TEST(PlateShear, PlateFeelsStokesWallShear) {
  const validation::PlateShearMeasurement m =
      validation::measure_plate_shear("reference", validation::plate_shear_scene(0.02, 10.0));
  EXPECT_NEAR(m.ratio, 1.0, 0.10);
}

TEST(PlateShear, FreeSlipPlateFailsTheCheck) {
  const validation::PlateShearMeasurement m = validation::measure_plate_shear(
      "reference", validation::plate_shear_scene(0.02, 10.0, {"materials/plate/viscosity=0"}));
  EXPECT_GT(std::abs(m.ratio - 1.0), 0.10);
}

}  // namespace
}  // namespace mssph::testing
