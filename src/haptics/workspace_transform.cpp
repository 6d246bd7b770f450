#include "haptics/workspace_transform.hpp"

namespace mssph {

WorkspaceTransform::WorkspaceTransform(double scale, const Eigen::Vector3d& offset, const Eigen::Quaterniond& rotation)
    : scale_(scale), offset_(offset), rotation_(rotation.normalized()) {}

Pose WorkspaceTransform::to_scene(const Pose& device) const {
  return Pose{offset_ + scale_ * (rotation_ * device.position), (rotation_ * device.orientation).normalized()};
}

Twist WorkspaceTransform::to_scene(const Twist& device) const {
  return Twist{scale_ * (rotation_ * device.linear), rotation_ * device.angular};
}

Pose WorkspaceTransform::to_device(const Pose& scene) const {
  return Pose{rotation_.conjugate() * (scene.position - offset_) / scale_,
              (rotation_.conjugate() * scene.orientation).normalized()};
}

Twist WorkspaceTransform::to_device(const Twist& scene) const {
  return Twist{rotation_.conjugate() * scene.linear / scale_, rotation_.conjugate() * scene.angular};
}

}  // namespace mssph
