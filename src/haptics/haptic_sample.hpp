#pragma once
// What one haptic tick produces: everything the user would feel and what it came from. The
// session hands each sample to its sinks (the run log, a device recording, a test).
#include "util/pose.hpp"

namespace mssph {

struct HapticSample {
  double time = 0.0;  // simulated time of the tick [s]
  Pose device_pose;   // handle, device frame
  Twist device_twist;
  Pose proxy_pose;  // proxy's centre of mass and orientation, scene frame
  Twist proxy_twist;
  Wrench interaction;  // sum of SPH interaction forces on the proxy and their torque (paper eq. 8, 9)
  Wrench coupling;     // virtual coupling wrench on the proxy, scene frame
  Wrench rendered;     // what the device renders at the handle, device frame, scaled and clamped
  bool force_saturated = false;
  bool torque_saturated = false;
  bool workspace_limited = false;  // the handle met the workspace boundary during the last tick
  double force_jump = 0.0;         // |rendered force - previous tick's| [N]
  double injected_energy = 0.0;    // energy the coupling has put into proxy and handle so far [J]
};

class HapticSink {
 public:
  virtual ~HapticSink() = default;
  virtual void record(const HapticSample& sample) = 0;
};

}  // namespace mssph
