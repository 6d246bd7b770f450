#include "util/pose.hpp"

#include <cmath>

namespace mssph {

Eigen::Vector3d rotation_vector(const Eigen::Quaterniond& q) {
  const double sign = q.w() < 0.0 ? -1.0 : 1.0;
  const Eigen::Vector3d v = sign * q.vec();
  const double w = sign * q.w();
  const double s = v.norm();
  // angle = 2 atan2(|v|, w); near zero, 2 atan2(s, w) / s -> 2 / w keeps full precision.
  if (s < 1e-12) return (2.0 / w) * v;
  return (2.0 * std::atan2(s, w) / s) * v;
}

Eigen::Quaterniond rotated(const Eigen::Quaterniond& q, const Eigen::Vector3d& rotation) {
  const double angle = rotation.norm();
  if (angle == 0.0) return q;
  return (Eigen::Quaterniond(Eigen::AngleAxisd(angle, rotation / angle)) * q).normalized();
}

}  // namespace mssph
