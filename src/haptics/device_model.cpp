#include "haptics/device_model.hpp"

namespace mssph {
namespace {

// Scales v down to length `limit` when longer; returns whether it did.
bool clamp_norm(Eigen::Vector3d& v, double limit) {
  const double norm = v.norm();
  if (norm <= limit) return false;
  v *= limit / norm;
  return true;
}

}  // namespace

RenderedWrench DeviceModel::render(const Wrench& coupling_on_proxy, const WorkspaceTransform& workspace) const {
  RenderedWrench out;
  out.wrench.force = config_.force_scale * workspace.direction_to_device(-coupling_on_proxy.force);
  out.wrench.torque = config_.torque_scale * workspace.direction_to_device(-coupling_on_proxy.torque);
  out.force_saturated = clamp_norm(out.wrench.force, config_.max_force);
  out.torque_saturated = clamp_norm(out.wrench.torque, config_.max_torque);
  return out;
}

bool DeviceModel::advance(DeviceState& state, const Wrench& applied, double dt) const {
  Twist& v = state.twist;
  v.linear += (applied.force - config_.linear_damping * v.linear) / config_.mass * dt;
  v.angular += (applied.torque - config_.angular_damping * v.angular) / config_.inertia * dt;
  state.pose.position += v.linear * dt;
  state.pose.orientation = rotated(state.pose.orientation, v.angular * dt);

  const double distance = state.pose.position.norm();
  if (distance <= config_.workspace_radius) return false;
  const Eigen::Vector3d normal = state.pose.position / distance;
  state.pose.position = config_.workspace_radius * normal;
  const double outward = v.linear.dot(normal);
  if (outward > 0.0) v.linear -= outward * normal;
  return true;
}

}  // namespace mssph
