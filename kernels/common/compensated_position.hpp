#pragma once
// Step 4's position update, x_{n+1} = x_n + v_{n+1/2} dt, in float32 without dropping what the sum
// rounds off. The sum rounds to the float32 spacing of x: 1.5e-8 m at 0.2 m from the kernel
// frame's origin, more than the displacement of a particle at 1 mm/s over a stiff fluid's step.
// Rounded every step the same way, such a particle moves at a rounded speed (or not at all), and
// the flow carries a drag from rounding (results/decisions/063). The part rounded off is found
// exactly (TwoSum: Knuth, TAOCP vol. 2, 4.2.2, theorem B) and added to the next step's
// displacement (compensated summation: Kahan 1965, Comm. ACM 8(1) 40), so it no longer adds up.
#include "particle_views.hpp"
#include "vec_math.hpp"

#include <cstdint>

namespace mssph::kernels {

// s = a + b rounded, and the exact error: a + b = sum + error (TwoSum, valid for any a, b).
struct ExactSum {
  float sum;
  float error;
};
MSSPH_HD ExactSum two_sum(float a, float b) {
  const float sum = a + b;
  const float b_part = sum - a;
  return {sum, (a - (sum - b_part)) + (b - b_part)};
}

// A rigid body's centre, which carries its rounding error exactly in a Vec3 of its own.
MSSPH_HD void add_compensated(Vec3& position, Vec3& carry, Vec3 displacement) {
  const Vec3 d = displacement + carry;
  const ExactSum x = two_sum(position.x, d.x), y = two_sum(position.y, d.y), z = two_sum(position.z, d.z);
  position = {x.sum, y.sum, z.sum};
  carry = {x.error, y.error, z.error};
}

// A particle's carry fits in the fourth component of its velocity record, so that memory per
// particle does not grow: each coordinate's error, at most half of that coordinate's float32
// spacing, as a 10-bit integer in units of 1/1024 of the spacing (kCarryUnits). What is lost is
// the rounding of that integer, at most 1/2048 of the spacing per step instead of 1/2. The 30 bits
// leave the float's top exponent bit clear: the pattern is never a NaN, so copies keep it.
inline constexpr float kCarryUnits = 1024.0f;
inline constexpr std::int32_t kCarryLimit = 511;  // the largest 10-bit two's complement magnitude

// The spacing between float32 values at |x| (the unit in the last place, not below 2^-126's).
MSSPH_HD float float_spacing(float x) {
  const std::uint32_t exponent = index_from_float_bits(x) & 0x7f800000u;
  const std::uint32_t at_least_normal = exponent > (23u << 23) ? exponent : (24u << 23);
  return index_as_float_bits(at_least_normal) * 0x1p-23f;
}

MSSPH_HD float carry_component(float carry, int axis) {
  const std::uint32_t field = (index_from_float_bits(carry) >> (10 * axis)) & 0x3ffu;
  return static_cast<float>(static_cast<std::int32_t>(field << 22) >> 22);  // sign-extended
}

// The carry of `error` (the part of coordinate `stored` rounded off), on `axis`'s 10 bits.
// Rounded to the nearest unit by a cast, without a call to the maths library.
MSSPH_HD std::uint32_t carry_field(float stored, float error, int axis) {
  const float scaled = error / float_spacing(stored) * kCarryUnits;  // within [-512, 512]
  std::int32_t units = static_cast<std::int32_t>(scaled + (scaled < 0.0f ? -0.5f : 0.5f));
  units = units < -kCarryLimit ? -kCarryLimit : (units > kCarryLimit ? kCarryLimit : units);
  return (static_cast<std::uint32_t>(units) & 0x3ffu) << (10 * axis);
}

// x_{n+1} = x_n + displacement, plus the carry of the last step, which it replaces: the packed
// carry unpacked, the rigid body's update, and its exact carry packed again.
MSSPH_HD void move_compensated(Vec3& position, float& carry, Vec3 displacement) {
  Vec3 exact{carry_component(carry, 0) * (float_spacing(position.x) / kCarryUnits),
             carry_component(carry, 1) * (float_spacing(position.y) / kCarryUnits),
             carry_component(carry, 2) * (float_spacing(position.z) / kCarryUnits)};
  add_compensated(position, exact, displacement);
  carry = index_as_float_bits(carry_field(position.x, exact.x, 0) | carry_field(position.y, exact.y, 1) |
                              carry_field(position.z, exact.z, 2));
}

}  // namespace mssph::kernels
