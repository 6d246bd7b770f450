#include "haptics/haptic_metrics.hpp"

#include <algorithm>

namespace mssph {

void HapticMetrics::record(const HapticSample& s) {
  ++ticks;
  force_saturated_ticks += s.force_saturated ? 1 : 0;
  torque_saturated_ticks += s.torque_saturated ? 1 : 0;
  workspace_limited_ticks += s.workspace_limited ? 1 : 0;
  saturated_ticks += (s.force_saturated || s.torque_saturated || s.workspace_limited) ? 1 : 0;
  peak_rendered_force = std::max(peak_rendered_force, s.rendered.force.norm());
  peak_rendered_torque = std::max(peak_rendered_torque, s.rendered.torque.norm());
  max_force_jump = std::max(max_force_jump, s.force_jump);
  energy_balance = s.injected_energy;
  max_injected_energy = std::max(max_injected_energy, s.injected_energy);
}

}  // namespace mssph
