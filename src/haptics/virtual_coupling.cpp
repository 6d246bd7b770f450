#include "haptics/virtual_coupling.hpp"

namespace mssph {

Eigen::Vector3d orientation_error(const Eigen::Quaterniond& target, const Eigen::Quaterniond& follower) {
  return rotation_vector(target * follower.conjugate());  // rotation_vector flips w < 0
}

Wrench spring_damper_wrench(const SpringDamperGains& gains, const Pose& target, const Twist& target_twist,
                            const Pose& follower, const Twist& follower_twist) {
  Wrench w;
  w.force = gains.linear_stiffness * (target.position - follower.position) +
            gains.linear_damping * (target_twist.linear - follower_twist.linear);
  w.torque = gains.angular_stiffness * orientation_error(target.orientation, follower.orientation) +
             gains.angular_damping * (target_twist.angular - follower_twist.angular);
  return w;
}

}  // namespace mssph
