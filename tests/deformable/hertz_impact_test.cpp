// Hertz impact (validation/physics/hertz_impact): a rigid sphere striking an elastic block, on the
// cpu backend at the quick case's spacing (2 cm, maximum indentation 2 dx), against Hertz's
// impact theory within the case's 15 %; the same measurement against a block taken as twice as
// stiff as it is FAILs, so the checks tell materials apart. Johnson's contact duration against
// the numerical integration of the equation of motion.
#include "physics/hertz_impact/hertz_impact.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mssph {
namespace {

// Johnson's duration 2.94 d* / V is the integral of m d'' = -K d^1.5 over the pulse, rounded.
TEST(HertzImpact, JohnsonsDurationAgreesWithTheEquationOfMotion) {
  const validation::HertzImpact h = validation::hertz_impact(67.0, 0.5, 1.0e5, 1e-12);
  EXPECT_NEAR(h.duration_above / h.duration, 1.0, 2e-3);
}

TEST(HertzImpact, SphereOnBlockFollowsHertzAndNotATwiceStifferBlock) {
  const validation::HertzImpactMeasurement m =
      validation::measure_hertz_impact("cpu", validation::hertz_impact_scene(0.02));
  const auto relative = [](double measured, double expected) { return std::abs(measured / expected - 1.0); };
  const validation::HertzImpact right =
      validation::hertz_impact(m.mass, m.speed, m.stiffness, validation::kPulseFraction);
  EXPECT_LT(relative(m.max_indentation, right.max_indentation), 0.15);
  EXPECT_LT(relative(m.peak_force, right.peak_force), 0.15);
  EXPECT_LT(relative(m.duration_above, right.duration_above), 0.15);
  const validation::HertzImpact planted =
      validation::hertz_impact(m.mass, m.speed, 2.0 * m.stiffness, validation::kPulseFraction);
  EXPECT_GT(relative(m.max_indentation, planted.max_indentation), 0.15);
  EXPECT_GT(relative(m.peak_force, planted.peak_force), 0.15);
  EXPECT_GT(relative(m.duration_above, planted.duration_above), 0.15);
  EXPECT_TRUE(m.left_block) << "the sphere must leave the block within the scene's duration";
}

}  // namespace
}  // namespace mssph
