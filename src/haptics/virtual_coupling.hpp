#pragma once
// The 6DoF spring-damper of a virtual coupling (Colgate, Stanley and Brown 1995; docs/model.md
// section 4), pulling a follower towards a target:
//   F   = Kt (p_d - p) + Bt (v_d - v)
//   q_e = q_d conj(q), negated when its w < 0 so that the error rotation is the short way (<= pi)
//   tau = Kr angle(q_e) axis(q_e) + Br (w_d - w)
// The coupling uses it with the handle (mapped into the scene) as target and the proxy as
// follower: the proxy receives (+F, +tau) on top of its SPH interaction wrench (paper eq. 8, 9)
// and the device renders (-F, -tau). The simulated hand uses it with the scripted target and the
// handle.
#include "config/haptics_config.hpp"
#include "util/pose.hpp"

namespace mssph {

Wrench spring_damper_wrench(const SpringDamperGains& gains, const Pose& target, const Twist& target_twist,
                            const Pose& follower, const Twist& follower_twist);

// angle(q_e) axis(q_e) for q_e = target conj(follower), the short way.
Eigen::Vector3d orientation_error(const Eigen::Quaterniond& target, const Eigen::Quaterniond& follower);

}  // namespace mssph
