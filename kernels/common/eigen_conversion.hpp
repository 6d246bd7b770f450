#pragma once
// The one conversion between the Backend interface's double vectors (Eigen) and the kernels'
// float32 vectors, used by every float backend: a double is rounded to the nearest float once.
#include "vec_math.hpp"

#include <Eigen/Core>

namespace mssph::kernels {

inline Vec3 to_vec3(const Eigen::Vector3d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}
inline Eigen::Vector3d to_eigen(Vec3 v) { return {v.x, v.y, v.z}; }
inline Mat3 to_mat3(const Eigen::Matrix3d& m) {
  Mat3 out;
  for (int k = 0; k < 9; ++k) out.m[k] = static_cast<float>(m(k / 3, k % 3));
  return out;
}

}  // namespace mssph::kernels
