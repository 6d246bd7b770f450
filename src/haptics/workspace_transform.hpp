#pragma once
// The map between the device's frame and the scene (docs/model.md): a similarity
//   p_scene = offset + s R p_device,  q_scene = R q_device,
//   v_scene = s R v_device,           w_scene = R w_device,
// and wrenches back to the device frame by R^T (the rendered wrench is scaled separately).
#include "util/pose.hpp"

namespace mssph {

class WorkspaceTransform {
 public:
  WorkspaceTransform(double scale, const Eigen::Vector3d& offset, const Eigen::Quaterniond& rotation);

  Pose to_scene(const Pose& device) const;
  Twist to_scene(const Twist& device) const;
  Pose to_device(const Pose& scene) const;
  Twist to_device(const Twist& scene) const;
  Eigen::Vector3d direction_to_device(const Eigen::Vector3d& scene) const { return rotation_.conjugate() * scene; }

 private:
  double scale_;
  Eigen::Vector3d offset_;
  Eigen::Quaterniond rotation_;
};

}  // namespace mssph
