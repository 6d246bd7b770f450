#pragma once
// Twin tests: each float32 equation function of kernels/common/ against its float64 twin of the
// same name in cpu_reference/, on many random inputs, one function at a time (the way MuJoCo's
// MJX checks each stage against its C engine).
//
// Inputs are drawn in double and rounded to float32 once; both twins then read the same values,
// so a difference measures the float32 arithmetic alone, never the rounding of the inputs.
//
// Tolerance. A difference is measured against `scale`, the size of the largest term the
// function adds or subtracts (not the result, which cancellation can make small): float32
// rounds each operation by at most u = 2^-24 = 6.0e-8 relative to its operands, and the
// functions here chain at most a few tens of roundings (a 3x3 product: 3 per entry, a sum over
// 40 bonds: 40 more), so their error stays below ~50 u = 3e-6 of the scale. kTolerance = 1e-5
// (about 170 u) leaves room for that and for sqrt, log and division, and is still far below
// any formula error: an error in a term shows at the term's size.
//
// Every comparison can fail: it also counts the draws where the expected value is at least
// 1000 kTolerance scale (1 % of the scale) and requires that most draws are such, so the
// tolerance band is at most 1e-3 of the quantity checked and a wrong term, sign or factor in
// the float function exceeds it.
#include "common/vec_math.hpp"

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <utility>

namespace mssph::testing {

inline constexpr double kTolerance = 1e-5;
inline constexpr int kDraws = 2000;

// Random inputs rounded to float32. The seed is fixed (printed, and MSSPH_TWIN_SEED overrides
// it to explore others).
class TwinDraws {
 public:
  explicit TwinDraws(const std::string& test) {
    std::uint64_t seed = 20110319;  // fixed: a failure reproduces
    if (const char* text = std::getenv("MSSPH_TWIN_SEED")) seed = std::strtoull(text, nullptr, 10);
    random_.seed(seed);
    std::cout << test << ": seed " << seed << " (MSSPH_TWIN_SEED overrides), " << kDraws << " draws\n";
  }

  // A float32 value in [low, high).
  double uniform(double low, double high) {
    return static_cast<float>(std::uniform_real_distribution<double>(low, high)(random_));
  }
  Eigen::Vector3d vector(double size) { return {uniform(-size, size), uniform(-size, size), uniform(-size, size)}; }
  Eigen::Matrix3d matrix(double size) {
    Eigen::Matrix3d m;
    for (int k = 0; k < 9; ++k) m(k / 3, k % 3) = uniform(-size, size);
    return m;
  }
  // A uniformly random rotation as a unit quaternion with float32 components (|q| = 1 to ~1e-7).
  Eigen::Quaterniond quaternion() {
    std::normal_distribution<double> normal;
    Eigen::Vector4d q(normal(random_), normal(random_), normal(random_), normal(random_));
    q.normalize();
    return Eigen::Quaterniond(static_cast<float>(q(3)), static_cast<float>(q(0)), static_cast<float>(q(1)),
                              static_cast<float>(q(2)));
  }
  // Its rotation matrix, rounded to float32 (orthogonal to ~1e-7; both twins read the same one).
  Eigen::Matrix3d rotation() { return rounded(quaternion().toRotationMatrix()); }

  static double rounded(double x) { return static_cast<float>(x); }
  template <class Derived>
  static typename Derived::PlainObject rounded(const Eigen::MatrixBase<Derived>& m) {
    return m.eval().template cast<float>().template cast<double>();
  }

 private:
  std::mt19937_64 random_;
};

// Float32 <-> float64 conversions (exact in the float-to-double direction).
inline kernels::Vec3 to_float(const Eigen::Vector3d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}
inline kernels::Vec4 to_float4(const Eigen::Vector3d& v, float w) { return kernels::make_vec4(to_float(v), w); }
inline kernels::Mat3 to_float(const Eigen::Matrix3d& m) {
  kernels::Mat3 f;
  for (int k = 0; k < 9; ++k) f.m[k] = static_cast<float>(m(k / 3, k % 3));  // row-major
  return f;
}
inline kernels::Quat to_float(const Eigen::Quaterniond& q) {
  return {static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z()), static_cast<float>(q.w())};
}
inline Eigen::Vector3d to_double(kernels::Vec3 v) { return {v.x, v.y, v.z}; }
inline Eigen::Matrix3d to_double(const kernels::Mat3& m) {
  Eigen::Matrix3d d;
  for (int k = 0; k < 9; ++k) d(k / 3, k % 3) = m.m[k];
  return d;
}
inline Eigen::Quaterniond to_double(kernels::Quat q) { return Eigen::Quaterniond(q.w, q.x, q.y, q.z); }

// Collects one quantity's differences over the draws and reports once: the worst draw (relative
// to its scale) must be within kTolerance, and at least `informative_share` of the draws must
// have an expected value of at least 1000 kTolerance scale (see the file comment).
class TwinComparison {
 public:
  explicit TwinComparison(std::string quantity, double informative_share = 0.9)
      : quantity_(std::move(quantity)), informative_share_(informative_share) {}
  TwinComparison(const TwinComparison&) = delete;
  TwinComparison& operator=(const TwinComparison&) = delete;

  void add(double got, double expected, double scale) { record(std::abs(got - expected), std::abs(expected), scale); }
  // Vectors by their Euclidean norm, matrices by their Frobenius norm.
  template <class Got, class Expected>
  void add(const Eigen::MatrixBase<Got>& got, const Eigen::MatrixBase<Expected>& expected, double scale) {
    record((got - expected).norm(), expected.norm(), scale);
  }

  ~TwinComparison() {
    EXPECT_GT(draws_, 0) << quantity_;
    std::cout << "  " << quantity_ << ": worst |float - double| / scale = " << worst_ << " (draw " << worst_draw_
              << "), informative draws " << informative_ << " of " << draws_ << "\n";
    EXPECT_LE(worst_, kTolerance) << quantity_ << ": draw " << worst_draw_ << " differs beyond float32 rounding";
    EXPECT_GE(informative_, informative_share_ * draws_)
        << quantity_ << ": too few draws where the quantity is far above the tolerance, the check could not fail";
  }

 private:
  void record(double difference, double expected_size, double scale) {
    EXPECT_GT(scale, 0.0) << quantity_ << ", draw " << draws_;
    double relative = scale > 0.0 ? difference / scale : difference;
    if (std::isnan(relative)) relative = std::numeric_limits<double>::infinity();
    if (relative > worst_) {
      worst_ = relative;
      worst_draw_ = draws_;
    }
    if (expected_size >= 1000.0 * kTolerance * scale) ++informative_;
    ++draws_;
  }

  std::string quantity_;
  double informative_share_;
  int draws_ = 0;
  int informative_ = 0;
  double worst_ = 0.0;
  int worst_draw_ = -1;
};

}  // namespace mssph::testing
