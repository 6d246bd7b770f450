#pragma once
// Poses, twists and wrenches of the haptic loop, SI units. A pose's orientation is a unit
// quaternion; files and logs store it scalar last (qx, qy, qz, qw), like the Virtuose's API.
#include <Eigen/Geometry>

namespace mssph {

struct Pose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // [m]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

struct Twist {
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();   // [m/s]
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();  // world-frame angular velocity [rad/s]
};

struct Wrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // [N]
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();  // [N m]
};

// The rotation vector (angle times unit axis) of q, taken the short way: q and -q are the same
// rotation, and the representative with w >= 0 has an angle in [0, pi].
Eigen::Vector3d rotation_vector(const Eigen::Quaterniond& q);

// exp(rotation) * q: q turned by the rotation vector `rotation` (world frame).
Eigen::Quaterniond rotated(const Eigen::Quaterniond& q, const Eigen::Vector3d& rotation);

}  // namespace mssph
