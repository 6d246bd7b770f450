#pragma once
// Float32 small-vector and 3x3 matrix arithmetic for the kernels (host and device). Plain
// aggregates, so arrays of them are structure-of-arrays friendly and 16-byte loads stay aligned.
#include "host_device.hpp"

#include <cmath>

namespace mssph::kernels {

struct Vec3 {
  float x, y, z;
};

// Positions and velocities are stored as 16-byte aligned quadruples: one vector load per
// particle. The fourth component carries a per-particle scalar where useful.
struct alignas(16) Vec4 {
  float x, y, z, w;
};

MSSPH_HD Vec3 make_vec3(float x, float y, float z) { return Vec3{x, y, z}; }
MSSPH_HD Vec3 xyz(const Vec4& v) { return Vec3{v.x, v.y, v.z}; }
MSSPH_HD Vec4 make_vec4(const Vec3& v, float w) { return Vec4{v.x, v.y, v.z, w}; }

MSSPH_HD Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
MSSPH_HD Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
MSSPH_HD Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
MSSPH_HD Vec3 operator*(float s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
MSSPH_HD Vec3 operator*(Vec3 a, float s) { return {s * a.x, s * a.y, s * a.z}; }
MSSPH_HD Vec3& operator+=(Vec3& a, Vec3 b) {
  a.x += b.x;
  a.y += b.y;
  a.z += b.z;
  return a;
}
MSSPH_HD Vec3& operator-=(Vec3& a, Vec3 b) {
  a.x -= b.x;
  a.y -= b.y;
  a.z -= b.z;
  return a;
}
MSSPH_HD float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
MSSPH_HD Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
MSSPH_HD float squared_norm(Vec3 a) { return dot(a, a); }
MSSPH_HD float norm(Vec3 a) { return std::sqrt(dot(a, a)); }

// x / y in a term of the neighbour sums. On the GPU the hardware approximation __fdividef, within
// 2 ulp for 2^-126 <= |y| <= 2^126 (CUDA C++ Programming Guide, mathematical functions' error
// bounds), for the reason PairDistance gives (smoothing_kernels.hpp); the host divides exactly.
MSSPH_HD float fast_quotient(float x, float y) {
#if defined(__CUDA_ARCH__)
  return __fdividef(x, y);
#else
  return x / y;
#endif
}

#if defined(__CUDA_ARCH__)
// 1 / sqrt(x) for a normal float x > 0 or +inf: the hardware approximation that rsqrtf takes
// (within 2 ulp, CUDA C++ Programming Guide), without the rescaling rsqrtf wraps around it for a
// subnormal x: for these arguments the same bits in fewer instructions. A subnormal or zero x is
// flushed to +0 and gives +inf; callers keep it out (pair_distance's coincidence test).
__device__ __forceinline__ float normal_rsqrt(float x) {
  float y;
  asm("rsqrt.approx.ftz.f32 %0, %1;" : "=f"(y) : "f"(x));
  return y;
}
#endif

// Row-major 3x3 matrix.
struct Mat3 {
  float m[9];
  MSSPH_HD float operator()(int r, int c) const { return m[3 * r + c]; }
  MSSPH_HD float& operator()(int r, int c) { return m[3 * r + c]; }
};

MSSPH_HD Mat3 zero_mat3() { return Mat3{{0, 0, 0, 0, 0, 0, 0, 0, 0}}; }
MSSPH_HD Mat3 identity_mat3() { return Mat3{{1, 0, 0, 0, 1, 0, 0, 0, 1}}; }
MSSPH_HD Vec3 operator*(const Mat3& a, Vec3 v) {
  return {a.m[0] * v.x + a.m[1] * v.y + a.m[2] * v.z, a.m[3] * v.x + a.m[4] * v.y + a.m[5] * v.z,
          a.m[6] * v.x + a.m[7] * v.y + a.m[8] * v.z};
}
MSSPH_HD Mat3 operator*(const Mat3& a, const Mat3& b) {
  Mat3 c = zero_mat3();
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k) {
      for (int col = 0; col < 3; ++col) c.m[3 * r + col] += a.m[3 * r + k] * b.m[3 * k + col];
    }
  }
  return c;
}
MSSPH_HD Mat3 operator+(const Mat3& a, const Mat3& b) {
  Mat3 c;
  for (int k = 0; k < 9; ++k) c.m[k] = a.m[k] + b.m[k];
  return c;
}
MSSPH_HD Mat3 operator-(const Mat3& a, const Mat3& b) {
  Mat3 c;
  for (int k = 0; k < 9; ++k) c.m[k] = a.m[k] - b.m[k];
  return c;
}
MSSPH_HD Mat3 operator*(float s, const Mat3& a) {
  Mat3 c;
  for (int k = 0; k < 9; ++k) c.m[k] = s * a.m[k];
  return c;
}
MSSPH_HD Mat3 transpose(const Mat3& a) {
  return Mat3{{a.m[0], a.m[3], a.m[6], a.m[1], a.m[4], a.m[7], a.m[2], a.m[5], a.m[8]}};
}
MSSPH_HD float trace(const Mat3& a) { return a.m[0] + a.m[4] + a.m[8]; }
// a (x) b = a b^T
MSSPH_HD Mat3 outer(Vec3 a, Vec3 b) {
  return Mat3{{a.x * b.x, a.x * b.y, a.x * b.z, a.y * b.x, a.y * b.y, a.y * b.z, a.z * b.x, a.z * b.y, a.z * b.z}};
}
MSSPH_HD Vec3 column(const Mat3& a, int c) { return {a.m[c], a.m[3 + c], a.m[6 + c]}; }
// The cofactor matrix cof A = det(A) A^-T, column by column: (a1 x a2, a2 x a0, a0 x a1).
MSSPH_HD Mat3 cofactor(const Mat3& a) {
  const Vec3 a0 = column(a, 0), a1 = column(a, 1), a2 = column(a, 2);
  const Vec3 c0 = cross(a1, a2), c1 = cross(a2, a0), c2 = cross(a0, a1);
  return Mat3{{c0.x, c1.x, c2.x, c0.y, c1.y, c2.y, c0.z, c1.z, c2.z}};
}
MSSPH_HD float determinant(const Mat3& a) { return dot(column(a, 0), cross(column(a, 1), column(a, 2))); }

// Unit quaternion (x, y, z, w), scalar last like the Virtuose's pose.
struct Quat {
  float x, y, z, w;
};

MSSPH_HD Quat operator*(Quat a, Quat b) {
  return {a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y, a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
          a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w, a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}
MSSPH_HD Quat normalized(Quat q) {
  const float inv = 1.0f / std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  return {q.x * inv, q.y * inv, q.z * inv, q.w * inv};
}
// Rotation by `angle` [rad] about the unit `axis`.
MSSPH_HD Quat axis_angle(Vec3 axis, float angle) {
  const float s = std::sin(0.5f * angle);
  return {s * axis.x, s * axis.y, s * axis.z, std::cos(0.5f * angle)};
}
MSSPH_HD Mat3 rotation_matrix(Quat q) {
  const float xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
  const float xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
  const float wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
  return Mat3{{1 - 2 * (yy + zz), 2 * (xy - wz), 2 * (xz + wy), 2 * (xy + wz), 1 - 2 * (xx + zz), 2 * (yz - wx),
               2 * (xz - wy), 2 * (yz + wx), 1 - 2 * (xx + yy)}};
}

}  // namespace mssph::kernels
