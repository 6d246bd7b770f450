#pragma once
// The handle of a simulated Virtuose 6D (docs/model.md): what its motors can render, and
// its motion, in the device frame, under the motors, the hand and its own mass and damping.
#include "config/haptics_config.hpp"
#include "haptics/workspace_transform.hpp"
#include "util/pose.hpp"

namespace mssph {

struct DeviceState {
  Pose pose;    // device frame
  Twist twist;  // device frame
};

struct RenderedWrench {
  Wrench wrench;  // at the handle, device frame
  bool force_saturated = false;
  bool torque_saturated = false;
};

class DeviceModel {
 public:
  explicit DeviceModel(const DeviceConfig& config) : config_(config) {}

  // The motors render the coupling's reaction (-F, -tau): into the device frame, times
  // force_scale and torque_scale, each clamped to its limit with its direction kept.
  RenderedWrench render(const Wrench& coupling_on_proxy, const WorkspaceTransform& workspace) const;

  // Advances the handle by dt under `applied` (motors plus hand) and its own damping, by
  // semi-implicit Euler like the rigid bodies of the simulation:
  //   v += (F - b v) / m dt,  x += v dt,  w += (tau - b_r w) / I dt,  q = exp(w dt) q.
  // The workspace boundary is a mechanical stop: the handle is held on the sphere of
  // workspace_radius and its outward velocity removed. Returns whether the stop was hit.
  bool advance(DeviceState& state, const Wrench& applied, double dt) const;

 private:
  DeviceConfig config_;
};

}  // namespace mssph
