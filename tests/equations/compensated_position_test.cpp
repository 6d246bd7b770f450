// The compensated position update (kernels/common/compensated_position.hpp) against exact sums in
// float64: a slow particle's and a slow rigid body's float32 path over many steps. Each long
// test also takes the same path with the plain float32 sum, which the tolerance must reject: the
// error the update removes is there to be found.
#include "common/compensated_position.hpp"
#include "common/fluid_physics.hpp"
#include "common/rigid_physics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace mssph::testing {
namespace {

using kernels::Vec3;
using kernels::Vec4;

TEST(CompensatedPosition, TwoSumErrorIsExact) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> position(-1.0f, 1.0f), step(-1e-6f, 1e-6f);
  for (int k = 0; k < 100000; ++k) {
    const float a = position(random), b = k % 2 ? step(random) : position(random);
    const kernels::ExactSum s = kernels::two_sum(a, b);
    ASSERT_EQ(static_cast<double>(a) + static_cast<double>(b),
              static_cast<double>(s.sum) + static_cast<double>(s.error))
        << a << " + " << b;
  }
}

TEST(CompensatedPosition, FloatSpacingIsTheGapToTheNextValue) {
  for (const float x : {0.2f, -0.2f, 1.0f, 0.125f, 3.0e-3f, 7.0f, 1.0e-30f}) {
    EXPECT_EQ(kernels::float_spacing(x), std::nextafter(std::fabs(x), 1.0e30f) - std::fabs(x)) << x;
  }
  EXPECT_GT(kernels::float_spacing(0.0f), 0.0f);
}

// Each coordinate's carry survives packing to the 1/1024 of its spacing, the sign included.
TEST(CompensatedPosition, CarryKeepsEachCoordinatesError) {
  const Vec3 stored{0.2f, -0.05f, 1.5f};
  const Vec3 error{0.3f * kernels::float_spacing(0.2f), -0.49f * kernels::float_spacing(0.05f),
                   -0.001f * kernels::float_spacing(1.5f)};
  const float carry = kernels::index_as_float_bits(kernels::carry_field(stored.x, error.x, 0) |
                                                   kernels::carry_field(stored.y, error.y, 1) |
                                                   kernels::carry_field(stored.z, error.z, 2));
  EXPECT_FALSE(std::isnan(carry));
  EXPECT_EQ(kernels::carry_component(carry, 0), std::nearbyint(0.3f * 1024.0f));
  EXPECT_EQ(kernels::carry_component(carry, 1), std::nearbyint(-0.49f * 1024.0f));
  EXPECT_EQ(kernels::carry_component(carry, 2), -1.0f);
}

// A particle 0.2 m from the origin (float spacing 1.5e-8 m) moving at 1e-4 m/s with dt = 1e-4 s:
// each step's displacement, 1e-8 m, is two thirds of a spacing, so the plain sum rounds every step
// up to a whole spacing and the particle moves 49 % too fast. The leap-frog (no force, no gravity)
// moves it by v t over 20000 steps within the worst case of the carry's own rounding, 1/2048 of a
// spacing per step, plus one spacing: 0.08 % of the 2e-4 m travelled.
TEST(CompensatedPosition, SlowParticleMovesAtItsSpeed) {
  kernels::StepParameters step{};
  step.dt = 1.0e-4f;
  const float speed = 1.0e-4f;
  const int steps = 20000;
  Vec4 position{0.2f, -0.2f, 0.05f, 0.0f}, velocity{speed, -speed, 0.0f, 0.0f};
  float plain_x = position.x;
  for (int n = 0; n < steps; ++n) {
    kernels::leapfrog(position, velocity, Vec3{0, 0, 0}, 1.0f, false, step);
    plain_x = plain_x + step.dt * speed;
  }
  const double travelled = static_cast<double>(steps) * static_cast<double>(step.dt) * speed;
  const double bound = steps * kernels::float_spacing(0.2f) / 2048.0 + kernels::float_spacing(0.2f);
  EXPECT_NEAR(position.x - 0.2, static_cast<double>(0.2f) - 0.2 + travelled, bound);
  EXPECT_NEAR(position.y + 0.2, -(static_cast<double>(0.2f) - 0.2) - travelled, bound);
  EXPECT_EQ(position.z, 0.05f);
  EXPECT_GT(std::fabs(plain_x - static_cast<double>(0.2f) - travelled), 0.4 * travelled);  // the plain sum
}

// A rigid body's centre at 0.2 m towed at 1e-4 m/s: its carry is exact, so after 20000 steps the
// centre lies within one spacing of x0 + v t; the plain sum is again 49 % off.
TEST(CompensatedPosition, SlowRigidBodyMovesAtItsSpeed) {
  kernels::RigidBody body{};
  body.mass = 1.0f;
  body.position = {0.2f, 0.0f, 0.0f};
  body.velocity = {1.0e-4f, 0.0f, 0.0f};
  body.orientation = {0.0f, 0.0f, 0.0f, 1.0f};
  const float dt = 1.0e-4f;
  const int steps = 20000;
  float plain_x = body.position.x;
  for (int n = 0; n < steps; ++n) {
    kernels::integrate_rigid_body(body, Vec3{0, 0, 0}, dt);
    plain_x = plain_x + dt * body.velocity.x;
  }
  const double expected = static_cast<double>(0.2f) + steps * static_cast<double>(dt * body.velocity.x);
  EXPECT_NEAR(body.position.x, expected, kernels::float_spacing(0.2f));
  EXPECT_GT(std::fabs(plain_x - expected), 0.4 * (expected - 0.2));  // the plain sum
}

}  // namespace
}  // namespace mssph::testing
